# viewer/embed.cmake
# cmake -DIN=hmira-viewer.js -DOUT=hmira_viewer_bundle.inc -P embed.cmake
# Turns the viewer bundle into one C++ raw string literal that cmd_view.cpp includes.
file(READ "${IN}" bundle)
string(FIND "${bundle}" ")hmira_viewer_js\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )hmira_viewer_js\"; change it in viewer/embed.cmake")
endif()
file(WRITE "${OUT}.tmp" "R\"hmira_viewer_js(${bundle})hmira_viewer_js\"\n")
file(RENAME "${OUT}.tmp" "${OUT}")
