// How deeply a hand-written file (a board preset, a config file) may nest,
// checked on its text before anything parses it.
//
// Depth counts containers from the top of the document to its deepest
// value: JSON objects and arrays; TOML tables (the document itself, each
// part of a table header or of a dotted key before its last) and arrays (an
// array of tables is the array and its element), inline tables included.
// {"board": {"m": {"value": 4, "source": "s"}}} and "[board]\nm = 4" nest 3
// and 2 deep.
#pragma once

#include <cstddef>
#include <string>

namespace cdvp {

// The shipped presets nest 3 deep and a config file needs 3 at most; 64
// leaves room for any file written by hand, while the code that recurses
// once a level (cdvp's walks of the parsed tree, and toml::parse itself,
// which overflows an 8 MiB stack at about 130,000 levels: 260 KB of "a.")
// stays a few kilobytes deep whatever the 1 MiB size cap lets through.
constexpr int kMaxNesting = 64;

// Throw InputError "PATH:LINE:COLUMN: nesting deeper than 64 levels; WHAT
// nests objects and arrays at most 64 deep" (TOML: "tables and arrays") at
// the container that goes past the limit; 'what' is the file's kind ("a
// board preset"). Text that does not parse is left to the parser: these
// read only as far as nesting goes, and refuse nothing else.
void check_json_nesting(const std::string& path, const std::string& text, const std::string& what);
void check_toml_nesting(const std::string& path, const std::string& text, const std::string& what);

// "PATH:LINE:COLUMN" of the byte at 'offset' of 'text': lines and columns
// counted from 1, columns in bytes.
std::string text_position(const std::string& path, const std::string& text, std::size_t offset);

}  // namespace cdvp
