// The trace format: one box a line, frames as contiguous runs of rows.
//
//   frame,id,min_x,min_y,min_z,max_x,max_y,max_z
//   0,10,0,0,0,1,1,1
//
// Lines: LF or CRLF ends, at most 4096 bytes a line counting its line end
// (kMaxLineBytes), an optional UTF-8 byte order mark before the header,
// printable text only (tab allowed); see csv_reader.h. Spaces and tabs
// around a field are ignored; blank lines are allowed only at the end.
//
// frame, id: decimal integers 0 .. 2^64-1, digits only (leading zeros allowed;
// no sign, fraction, exponent, hex or inner space). Frame numbers ascend
// (gaps allowed) with each frame's rows contiguous; ids are unique within a
// frame.
//
// Coordinates: numbers as strtod reads them in the "C" locale, of any length
// within the line: decimal (1, -0, 2.5e-3, a 200-digit decimal) or hex
// (0x1p-3); inf / -inf / infinity in any case for unbounded sides. Each is
// rounded to the nearest double, so a value below the smallest denormal
// becomes a signed zero. Refused: NaN in any spelling, and finite spellings
// beyond the double range (1e999): strtod would return an infinity the user
// did not write. min <= max on every axis (-0 and +0 are equal). See
// docs/numerics.md for what the board then does with the doubles.
//
// A reader may limit the boxes of one frame and the frames (TraceLimits); the
// row that goes beyond a limit fails, before the rest of the file is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "sw/scene/csv_reader.h"
#include "sw/scene/scene.h"

namespace cdvp {

// The header line, without line end.
extern const char* const kTraceCsvHeader;

struct TraceLimits {
    // Most boxes one frame may hold.
    std::size_t max_boxes_per_frame = std::numeric_limits<std::size_t>::max();
    // Why, for the error message: "... expected at most N boxes a frame (WHY)".
    std::string reason = "the limit";
    // Most frames the trace may hold, and why.
    uint64_t max_frames = std::numeric_limits<uint64_t>::max();
    std::string frames_reason = "the limit";
};

// Reads a trace one frame at a time, so memory is bounded by the largest
// frame rather than the file. Throws InputError "NAME:LINE: message" on the
// first problem found.
class TraceReader {
public:
    // Reads and checks the header.
    TraceReader(std::istream& in, std::string name, TraceLimits limits = {});

    // The next frame, fully checked; nullopt after the last one.
    std::optional<Frame> next_frame();

private:
    struct Row {
        uint64_t frame;
        uint64_t id;
        Box box;
    };
    bool read_row(Row& row);
    void add(Frame& frame, const Row& row);
    void check_unique_ids(const Frame& frame, std::size_t first_line) const;

    CsvReader reader_;
    TraceLimits limits_;
    std::optional<Row> pending_;  // first row of the next frame, already read
    uint64_t frames_ = 0;         // returned so far
};

// Parses a whole trace into memory; 'name' prefixes error messages.
std::vector<Frame> parse_trace_csv(std::istream& in, const std::string& name,
                                   const TraceLimits& limits = {});

// Opens and parses 'path'; InputError "PATH: cannot open: <reason>" if the
// file cannot be opened.
std::vector<Frame> read_trace_csv(const std::string& path, const TraceLimits& limits = {});

// Writes frames in the same format; doubles with 17 significant digits so
// they read back bit-exact, infinities as inf / -inf. Frames without boxes
// produce no rows (and so do not come back on reading). Throws
// std::invalid_argument if a frame's ids and boxes differ in number.
void write_trace_csv(std::ostream& out, const std::vector<Frame>& frames);
// The same a frame at a time: the header, then each frame's rows.
void write_trace_header(std::ostream& out);
void write_trace_frame(std::ostream& out, const Frame& frame);

}  // namespace cdvp
