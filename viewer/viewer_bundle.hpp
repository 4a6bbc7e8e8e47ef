// viewer/viewer_bundle.hpp
// The viewer script (three.js + src/viewer.js) as text, compiled into a target by
// hmira_viewer_embed(<target>) in viewer/viewer.cmake; empty when the target was built without it.
#pragma once

#include <string_view>

namespace hmira_viewer {

/// The bundle's text, to pass to write_page(); empty when no bundle was embedded (then say how to
/// build it: viewer/build.sh, which needs node and npm, then re-run cmake).
inline std::string_view bundle() noexcept {
#ifdef HMIRA_VIEWER_BUNDLE
    // An array, not a constexpr string_view: its length is sizeof, not a compile-time strlen of 600 KB.
    static const char text[] =
#include "hmira_viewer_bundle.inc"
        ;
    return {text, sizeof text - 1};
#else
    return {};
#endif
}

}  // namespace hmira_viewer
