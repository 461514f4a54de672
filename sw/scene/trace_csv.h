// The trace format: one box a line, frames as contiguous runs of rows.
//
//   frame,id,min_x,min_y,min_z,max_x,max_y,max_z
//   0,10,0,0,0,1,1,1
//
// frame, id: non-negative decimal integers (uint64). Coordinates: numbers as
// strtod reads them in the "C" locale (+-inf allowed, NaN rejected). Frame
// numbers ascend (gaps allowed), ids are unique within a frame, min <= max.
// CRLF line ends and blank lines at the end of the file are accepted.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "sw/scene/scene.h"

namespace cdvp {

// The header line, without line end.
extern const char* const kTraceCsvHeader;

// Parses a whole trace; 'name' prefixes error messages. Throws InputError
// "NAME:LINE: message" on the first problem found.
std::vector<Frame> parse_trace_csv(std::istream& in, const std::string& name);

// Opens and parses 'path'; InputError "PATH: cannot open: <reason>" if the
// file cannot be opened.
std::vector<Frame> read_trace_csv(const std::string& path);

// Writes frames in the same format; doubles with 17 significant digits so
// they read back bit-exact, infinities as inf / -inf. Frames without boxes
// produce no rows (and so do not come back on reading). Throws
// std::invalid_argument if a frame's ids and boxes differ in number.
void write_trace_csv(std::ostream& out, const std::vector<Frame>& frames);

}  // namespace cdvp
