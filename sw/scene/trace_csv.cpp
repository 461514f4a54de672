#include "sw/scene/trace_csv.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace cdvp {

const char* const kTraceCsvHeader = "frame,id,min_x,min_y,min_z,max_x,max_y,max_z";

namespace {

constexpr std::size_t kFields = 8;
const char* const kFieldNames[kFields] = {"frame", "id",    "min_x", "min_y",
                                          "min_z", "max_x", "max_y", "max_z"};

// Appends v so that strtod reads back the same double. "%g" of an infinity is
// "inf" or "infinity" depending on the C library; spell it out.
void append_number(std::string& out, double v) {
    if (std::isinf(v)) {
        out += v > 0 ? "inf" : "-inf";
        return;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    out += buf;
}

}  // namespace

TraceReader::TraceReader(std::istream& in, std::string name, TraceLimits limits)
    : reader_(in, std::move(name)), limits_(std::move(limits)) {
    reader_.expect_header(kTraceCsvHeader);
}

bool TraceReader::read_row(Row& row) {
    if (!reader_.next_row(kFields)) {
        return false;
    }
    row.frame = reader_.uint_field(0, kFieldNames[0]);
    row.id = reader_.uint_field(1, kFieldNames[1]);
    for (int axis = 0; axis < 3; ++axis) {
        row.box.min[axis] = reader_.number_field(2 + axis, kFieldNames[2 + axis]);
        row.box.max[axis] = reader_.number_field(5 + axis, kFieldNames[5 + axis]);
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!(row.box.min[axis] <= row.box.max[axis])) {
            reader_.fail(std::string(kFieldNames[2 + axis]) + " (" +
                         shorten_found(reader_.field(2 + axis)) + ") is greater than " +
                         kFieldNames[5 + axis] + " (" +
                         shorten_found(reader_.field(5 + axis)) + "); expected min <= max");
        }
    }
    return true;
}

void TraceReader::add(Frame& frame, const Row& row) {
    if (frame.boxes.size() >= limits_.max_boxes_per_frame) {
        std::string limit = std::to_string(limits_.max_boxes_per_frame);
        reader_.fail("frame " + std::to_string(row.frame) + " has more than " + limit +
                     " boxes; expected at most " + limit + " boxes a frame (" +
                     limits_.reason + ")");
    }
    frame.ids.push_back(row.id);
    frame.boxes.push_back(row.box);
}

// A frame's rows sit on consecutive lines (blank lines end the file), so row
// k is on first_line + k. Sorting indices by id costs 8 bytes a box where a
// hash set of ids would cost several times that.
void TraceReader::check_unique_ids(const Frame& frame, std::size_t first_line) const {
    std::vector<std::size_t> order(frame.ids.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        order[k] = k;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return frame.ids[a] != frame.ids[b] ? frame.ids[a] < frame.ids[b] : a < b;
    });
    // Report the repeat that comes first in the file, as a line-by-line check would.
    std::size_t first = 0;
    std::size_t repeat = order.size();
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (frame.ids[order[k]] == frame.ids[order[k - 1]] &&
            (k == 1 || frame.ids[order[k - 2]] != frame.ids[order[k]]) && order[k] < repeat) {
            first = order[k - 1];
            repeat = order[k];
        }
    }
    if (repeat != order.size()) {
        reader_.fail_at(first_line + repeat,
                        "id " + std::to_string(frame.ids[repeat]) + " appears twice in frame " +
                            std::to_string(frame.number) + " (first on line " +
                            std::to_string(first_line + first) +
                            "); expected unique ids within a frame");
    }
}

std::optional<Frame> TraceReader::next_frame() {
    Row row;
    if (pending_) {
        row = *pending_;
        pending_.reset();
    } else if (!read_row(row)) {
        return std::nullopt;
    }
    if (frames_ == limits_.max_frames) {  // the row just read starts the frame beyond
        const std::string limit = std::to_string(limits_.max_frames);
        reader_.fail("frame " + std::to_string(row.frame) + " is one more than " + limit +
                     " frames; expected at most " + limit + " frames (" + limits_.frames_reason + ")");
    }
    ++frames_;
    Frame frame;
    frame.number = row.frame;
    std::size_t first_line = reader_.line();
    add(frame, row);
    while (read_row(row)) {
        if (row.frame == frame.number) {
            add(frame, row);
            continue;
        }
        if (row.frame < frame.number) {
            reader_.fail("frame " + std::to_string(row.frame) + " after frame " +
                         std::to_string(frame.number) +
                         "; expected ascending frame numbers with each frame's "
                         "rows contiguous");
        }
        pending_ = row;
        break;
    }
    check_unique_ids(frame, first_line);
    return frame;
}

std::vector<Frame> parse_trace_csv(std::istream& in, const std::string& name,
                                   const TraceLimits& limits) {
    TraceReader reader(in, name, limits);
    std::vector<Frame> frames;
    while (std::optional<Frame> frame = reader.next_frame()) {
        frames.push_back(std::move(*frame));
    }
    return frames;
}

std::vector<Frame> read_trace_csv(const std::string& path, const TraceLimits& limits) {
    std::ifstream in = open_input(path);
    return parse_trace_csv(in, path, limits);
}

namespace {

// A frame's rows appended to text, written out in chunks so a large trace
// is not held twice in memory.
void add_frame_rows(std::ostream& out, std::string& text, const Frame& frame) {
    if (frame.ids.size() != frame.boxes.size()) {
        throw std::invalid_argument("write_trace_csv: frame " +
                                    std::to_string(frame.number) +
                                    " has different numbers of ids and boxes");
    }
    for (std::size_t k = 0; k < frame.ids.size(); ++k) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "%" PRIu64 ",%" PRIu64, frame.number,
                      frame.ids[k]);
        text += buf;
        for (const double* bounds : {frame.boxes[k].min, frame.boxes[k].max}) {
            for (int axis = 0; axis < 3; ++axis) {
                text += ',';
                append_number(text, bounds[axis]);
            }
        }
        text += '\n';
        if (text.size() > (1u << 16)) {
            out << text;
            text.clear();
        }
    }
}

}  // namespace

void write_trace_csv(std::ostream& out, const std::vector<Frame>& frames) {
    std::string text = std::string(kTraceCsvHeader) + "\n";
    for (const Frame& frame : frames) add_frame_rows(out, text, frame);
    out << text;
}

void write_trace_header(std::ostream& out) { out << kTraceCsvHeader << '\n'; }

void write_trace_frame(std::ostream& out, const Frame& frame) {
    std::string text;
    add_frame_rows(out, text, frame);
    out << text;
}

}  // namespace cdvp
