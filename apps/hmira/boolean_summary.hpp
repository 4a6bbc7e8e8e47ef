// apps/hmira/boolean_summary.hpp
// What `hmira boolean` and `hmira repair --solid` print of a boolean_report: the output's counts
// and the report's fields, as JSON members and as the words of the summary line.
#pragma once

#include <cstdio>
#include <string>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>

#include "cli.hpp"

namespace hmira_cli {

/// The JSON members (no braces) for an output of `faces` faces and `vertices` vertices.
inline std::string boolean_report_json(const hmira::boolean_report& r, std::size_t faces, std::size_t vertices) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer,
                  "\"faces\": %zu, \"vertices\": %zu, \"intersecting_pairs\": %zu, \"cut_triangles\": %zu, "
                  "\"snapped_vertices\": %zu, \"degenerate_faces\": %zu, \"rounding_intersections\": %zu",
                  faces, vertices, r.intersecting_pairs, r.cut_triangles, r.snapped_vertices, r.degenerate_faces,
                  r.rounding_intersections);
    return buffer;
}

/// "<n> triangles; <c> cut triangles, <s> snapped vertices, <r> rounding intersections[, <d>
/// degenerate faces]" for an output of `faces` faces.
inline std::string boolean_report_words(const hmira::boolean_report& r, std::size_t faces) {
    std::string line = count_of(faces, "triangle", "triangles") + "; " +
                       count_of(r.cut_triangles, "cut triangle", "cut triangles") + ", " +
                       count_of(r.snapped_vertices, "snapped vertex", "snapped vertices") + ", " +
                       count_of(r.rounding_intersections, "rounding intersection", "rounding intersections");
    if (r.degenerate_faces > 0) line += ", " + count_of(r.degenerate_faces, "degenerate face", "degenerate faces");
    return line;
}

}  // namespace hmira_cli
