// libFuzzer target: the trace CSV parser (sw/scene/trace_csv.h).
//
// Invariants, each a crash when broken:
//  - no sanitizer report, no exception other than cdvp::InputError;
//  - a rejection is one line, "NAME:LINE: message", naming this input;
//  - an accepted trace written by write_trace_csv parses back to the same
//    frames, bit for bit (so -0, denormals and infinities survive).
// Memory is bounded by libFuzzer's -rss_limit_mb and -malloc_limit_mb.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "sw/scene/scene.h"
#include "sw/scene/trace_csv.h"

namespace {

const char* const kInputName = "fuzz.csv";

[[noreturn]] void violated(const std::string& what) {
    std::fprintf(stderr, "trace_fuzzer: invariant violated: %s\n", what.c_str());
    std::abort();
}

// "fuzz.csv:LINE: message" on one line.
void check_error_message(const std::string& message) {
    const std::string prefix = std::string(kInputName) + ":";
    std::size_t digits = prefix.size();
    while (digits < message.size() && std::isdigit(static_cast<unsigned char>(message[digits]))) ++digits;
    if (message.compare(0, prefix.size(), prefix) != 0 || digits == prefix.size() ||
        message.compare(digits, 2, ": ") != 0) {
        violated("error message does not start with \"" + prefix + "LINE: \": " + message);
    }
    if (message.find_first_of("\r\n") != std::string::npos) violated("error message is not one line: " + message);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_frame(const cdvp::Frame& a, const cdvp::Frame& b) {
    if (a.number != b.number || a.ids != b.ids || a.boxes.size() != b.boxes.size()) return false;
    for (std::size_t k = 0; k < a.boxes.size(); ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!same_bits(a.boxes[k].min[axis], b.boxes[k].min[axis]) ||
                !same_bits(a.boxes[k].max[axis], b.boxes[k].max[axis])) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::vector<cdvp::Frame> frames;
    try {
        frames = cdvp::parse_trace_csv(in, kInputName);
    } catch (const cdvp::InputError& e) {
        check_error_message(e.what());
        return 0;
    }

    std::ostringstream written;
    cdvp::write_trace_csv(written, frames);
    std::istringstream back(written.str());
    std::vector<cdvp::Frame> reread;
    try {
        reread = cdvp::parse_trace_csv(back, "round-trip.csv");
    } catch (const cdvp::InputError& e) {
        violated(std::string("an accepted trace, written back, is refused: ") + e.what());
    }
    if (reread.size() != frames.size()) {
        violated(std::to_string(frames.size()) + " frames came back as " + std::to_string(reread.size()));
    }
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (!same_frame(frames[f], reread[f])) {
            violated("frame " + std::to_string(frames[f].number) + " differs after writing and reading back");
        }
    }
    return 0;
}
