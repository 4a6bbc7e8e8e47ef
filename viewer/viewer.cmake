# viewer/viewer.cmake
# hmira_viewer_embed(<target>): compiles the viewer bundle (three.js + src/viewer.js, bundled
# by esbuild) into <target> as a string, for `hmira view`. The bundle comes from, in order:
#   HMIRA_VIEWER_BUNDLE (a built hmira-viewer.js), a build step when node and viewer/node_modules
#   are there (viewer/build.sh installs them), or viewer/dist/hmira-viewer.js, the bundle committed
#   to the repository (so every build has it, without node; viewer/check-bundle.sh checks that it
#   is what the sources make). Only if that file was deleted does the target build without a
#   bundle: then `hmira view` is refused with a usage error saying how to get it back.
set(HMIRA_VIEWER_BUNDLE "" CACHE FILEPATH "A built viewer bundle (hmira-viewer.js) to embed in hmira; empty: build or find one")
set(_hmira_viewer_dir ${CMAKE_CURRENT_LIST_DIR})

function(hmira_viewer_embed target)
  set(src ${_hmira_viewer_dir})
  set(bundle "${HMIRA_VIEWER_BUNDLE}")
  if(bundle AND NOT EXISTS "${bundle}")
    message(FATAL_ERROR "HMIRA_VIEWER_BUNDLE=${bundle} does not exist (viewer/build.sh writes viewer/dist/hmira-viewer.js)")
  endif()
  find_program(HMIRA_NODE node)
  if(NOT bundle AND HMIRA_NODE AND EXISTS ${src}/node_modules/three/package.json AND EXISTS ${src}/node_modules/esbuild/package.json)
    set(bundle ${CMAKE_CURRENT_BINARY_DIR}/viewer/hmira-viewer.js)
    file(GLOB js CONFIGURE_DEPENDS ${src}/src/*.js)
    add_custom_command(OUTPUT ${bundle} COMMAND ${HMIRA_NODE} ${src}/build.mjs ${bundle}
                       DEPENDS ${js} ${src}/build.mjs ${src}/package-lock.json COMMENT "Bundling the hmira viewer (three.js, esbuild)" VERBATIM)
  elseif(NOT bundle AND EXISTS ${src}/dist/hmira-viewer.js)
    set(bundle ${src}/dist/hmira-viewer.js)
  endif()
  target_include_directories(${target} PRIVATE ${src})  # viewer_page.hpp, viewer_bundle.hpp
  if(bundle)
    set(inc ${CMAKE_CURRENT_BINARY_DIR}/generated/hmira_viewer_bundle.inc)
    add_custom_command(OUTPUT ${inc} COMMAND ${CMAKE_COMMAND} -DIN=${bundle} -DOUT=${inc} -P ${src}/embed.cmake
                       DEPENDS ${bundle} ${src}/embed.cmake VERBATIM)
    target_sources(${target} PRIVATE ${inc})
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
    target_compile_definitions(${target} PRIVATE HMIRA_VIEWER_BUNDLE=1)
    message(STATUS "hmira view: viewer bundle ${bundle} is embedded")
  else()
    message(WARNING "hmira view: no viewer bundle: viewer/dist/hmira-viewer.js is missing (restore it from git, or run "
                    "viewer/build.sh, which needs node and npm, then re-run cmake); `hmira view` and hmira.view will refuse to run")
  endif()
endfunction()
