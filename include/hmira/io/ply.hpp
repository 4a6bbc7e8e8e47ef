// hmira/io/ply.hpp
// Stanford PLY in all three encodings (ASCII, binary little and big endian): the reader
// (read_ply, parse_ply; ply_reader.hpp) and the writer (write_ply, write_ply_to, format_ply;
// ply_writer.hpp).
#pragma once

#include "ply_reader.hpp"
#include "ply_writer.hpp"
