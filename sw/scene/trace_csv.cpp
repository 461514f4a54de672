#include "sw/scene/trace_csv.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "sw/scene/csv_reader.h"

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

std::vector<Frame> parse_trace_csv(std::istream& in, const std::string& name) {
    CsvReader reader(in, name);
    reader.expect_header(kTraceCsvHeader);

    std::vector<Frame> frames;
    std::unordered_map<uint64_t, std::size_t> id_lines;  // current frame's ids
    while (reader.next_row(kFields)) {
        uint64_t number = reader.uint_field(0, kFieldNames[0]);
        uint64_t id = reader.uint_field(1, kFieldNames[1]);
        Box box;
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = reader.number_field(2 + axis, kFieldNames[2 + axis]);
            box.max[axis] = reader.number_field(5 + axis, kFieldNames[5 + axis]);
        }
        for (int axis = 0; axis < 3; ++axis) {
            if (!(box.min[axis] <= box.max[axis])) {
                reader.fail(std::string(kFieldNames[2 + axis]) + " (" +
                            shorten_found(reader.field(2 + axis)) + ") is greater than " +
                            kFieldNames[5 + axis] + " (" +
                            shorten_found(reader.field(5 + axis)) +
                            "); expected min <= max");
            }
        }

        if (frames.empty() || number > frames.back().number) {
            frames.emplace_back();
            frames.back().number = number;
            id_lines.clear();
        } else if (number < frames.back().number) {
            reader.fail("frame " + std::to_string(number) + " after frame " +
                        std::to_string(frames.back().number) +
                        "; expected ascending frame numbers with each frame's "
                        "rows contiguous");
        }
        auto [it, inserted] = id_lines.emplace(id, reader.line());
        if (!inserted) {
            reader.fail("id " + std::to_string(id) + " appears twice in frame " +
                        std::to_string(number) + " (first on line " +
                        std::to_string(it->second) +
                        "); expected unique ids within a frame");
        }
        frames.back().ids.push_back(id);
        frames.back().boxes.push_back(box);
    }
    return frames;
}

std::vector<Frame> read_trace_csv(const std::string& path) {
    std::ifstream in = open_input(path);
    return parse_trace_csv(in, path);
}

void write_trace_csv(std::ostream& out, const std::vector<Frame>& frames) {
    std::string text = std::string(kTraceCsvHeader) + "\n";
    for (const Frame& frame : frames) {
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
        }
        // Write in chunks so a large trace is not held twice in memory.
        if (text.size() > (1u << 16)) {
            out << text;
            text.clear();
        }
    }
    out << text;
}

}  // namespace cdvp
