#include "sw/scene/pairs_csv.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <stdexcept>

#include "sw/scene/csv_reader.h"

namespace cdvp {

namespace {
const char* const kPairsHeader = "frame,a,b";
}  // namespace

std::vector<IdPair> to_id_pairs(const Frame& frame, const PairList& pairs) {
    std::vector<IdPair> out;
    out.reserve(pairs.size());
    for (const IndexPair& p : pairs) {
        uint64_t x = frame.ids.at(p.first);
        uint64_t y = frame.ids.at(p.second);
        out.push_back(x < y ? IdPair{x, y} : IdPair{y, x});
    }
    std::sort(out.begin(), out.end());
    return out;
}

void write_pairs_header(std::ostream& out) {
    out << kPairsHeader << '\n';
}

// In chunks, so that the text of a frame's pairs never sits in memory whole.
void write_frame_pairs(std::ostream& out, uint64_t frame, const std::vector<IdPair>& pairs) {
    constexpr std::size_t kChunkBytes = 1 << 16;
    std::string text;
    text.reserve(kChunkBytes + 72);
    char buf[72];
    for (const IdPair& p : pairs) {
        std::snprintf(buf, sizeof buf, "%" PRIu64 ",%" PRIu64 ",%" PRIu64 "\n", frame,
                      p.a, p.b);
        text += buf;
        if (text.size() >= kChunkBytes) {
            out << text;
            text.clear();
        }
    }
    out << text;
}

std::vector<std::pair<uint64_t, IdPair>> read_pairs_csv(const std::string& path) {
    std::ifstream in = open_input(path);
    CsvReader reader(in, path);
    reader.expect_header(kPairsHeader);
    std::vector<std::pair<uint64_t, IdPair>> rows;
    while (reader.next_row(3)) {
        uint64_t frame = reader.uint_field(0, "frame");
        IdPair pair{reader.uint_field(1, "a"), reader.uint_field(2, "b")};
        if (!(pair.a < pair.b)) {
            reader.fail("a (" + std::to_string(pair.a) + ") is not less than b (" +
                        std::to_string(pair.b) + "); expected a < b");
        }
        rows.emplace_back(frame, pair);
    }
    return rows;
}

}  // namespace cdvp
