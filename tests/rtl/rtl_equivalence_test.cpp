// The RTL behind the resource model computes what the C++ model computes:
// each Verilog piece runs under Icarus Verilog on vectors from these tests
// and its outputs are compared with the model's. Hard numeric cases (NaN,
// -0, infinities, denormals, equal bounds) are in every comparator vector set.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "models/address_generator/address_generator.h"
#include "models/board/board_core.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"

namespace cdvp {
namespace {

// A FIFO entry is wider than 64 bits at m = 32 (GCC's extension, as Verilog's wide vectors).
__extension__ typedef unsigned __int128 Word128;


const std::string kSource = CDVP_SOURCE_DIR;

// A scratch directory for one simulation, removed afterwards.
class Simulation {
public:
    Simulation() {
        char pattern[] = "/tmp/cdvp-rtl-XXXXXX";
        const char* made = mkdtemp(pattern);
        if (made == nullptr) throw std::runtime_error("mkdtemp failed");
        dir_ = made;
    }
    // CDVP_RTL_KEEP=1 keeps the directory (commands, results) for a look.
    ~Simulation() {
        if (std::getenv("CDVP_RTL_KEEP") == nullptr) std::system(("rm -rf '" + dir_ + "'").c_str());
    }
    const std::string& dir() const { return dir_; }

    void write_vectors(const std::vector<std::string>& lines, const std::string& name = "vectors.hex") const {
        std::ofstream out(dir_ + "/" + name);
        for (const std::string& line : lines) out << line << '\n';
    }
    // Compiles the testbench 'top' with 'sources' and parameters, runs it
    // with 'plusargs' and returns results.txt's lines.
    std::vector<std::string> run(const std::string& top, const std::vector<std::string>& sources,
                                 const std::vector<std::pair<std::string, std::string>>& parameters,
                                 const std::string& plusargs) const {
        std::string compile = std::string(CDVP_IVERILOG) + " -g2012 -o '" + dir_ + "/sim' -s " + top;
        for (const auto& [name, value] : parameters) compile += " -P" + top + "." + name + "=" + value;
        for (const std::string& source : sources) compile += " '" + kSource + "/" + source + "'";
        compile += " '" + kSource + "/tests/rtl/" + top + ".v'";
        EXPECT_EQ(std::system(compile.c_str()), 0) << compile;
        const std::string simulate = "cd '" + dir_ + "' && " + CDVP_VVP + " -n sim " + plusargs + " >/dev/null";
        EXPECT_EQ(std::system(simulate.c_str()), 0) << simulate;
        std::ifstream in(dir_ + "/results.txt");
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    }

private:
    std::string dir_;
};

std::string hex32(uint32_t word) {
    char text[9];
    std::snprintf(text, sizeof text, "%08x", word);
    return text;
}

// Bit patterns a float comparator gets wrong first.
std::vector<uint32_t> hard_floats() {
    const float specials[] = {0.0f,
                              -0.0f,
                              1.0f,
                              -1.0f,
                              1.5f,
                              -1.5f,
                              std::numeric_limits<float>::min(),
                              -std::numeric_limits<float>::min(),
                              std::numeric_limits<float>::denorm_min(),
                              -std::numeric_limits<float>::denorm_min(),
                              std::numeric_limits<float>::max(),
                              -std::numeric_limits<float>::max(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::nextafter(1.0f, 2.0f),
                              std::nextafter(1.0f, 0.0f)};
    std::vector<uint32_t> words;
    for (const float value : specials) words.push_back(ComparisonUnit::as_bits(value));
    words.push_back(0x7fc00000u);  // quiet NaN
    words.push_back(0xffc00001u);  // negative NaN with payload
    words.push_back(0x7f800001u);  // signalling NaN
    words.push_back(0x00400000u);  // a denormal
    return words;
}

TEST(FloatLeRtl, EqualsIeeeLessOrEqualOnHardAndRandomOperands) {
    std::vector<std::pair<uint32_t, uint32_t>> operands;
    const std::vector<uint32_t> hard = hard_floats();
    for (const uint32_t a : hard) {
        for (const uint32_t b : hard) operands.emplace_back(a, b);
    }
    std::mt19937 random(7);
    for (int k = 0; k < 3000; ++k) {
        const uint32_t a = random();
        // Every third pair shares its exponent, so the mantissa comparison decides.
        const uint32_t b = k % 3 == 0 ? (a & 0xff800000u) | (random() & 0x007fffffu) : random();
        operands.emplace_back(a, b);
    }
    std::vector<std::string> lines;
    for (const auto& [a, b] : operands) lines.push_back(hex32(a) + hex32(b));
    Simulation sim;
    sim.write_vectors(lines);
    const std::vector<std::string> results =
        sim.run("tb_float_le", {"models/comparison_unit/rtl/float_le.v"}, {},
                "+count=" + std::to_string(operands.size()));
    ASSERT_EQ(results.size(), operands.size());
    for (std::size_t v = 0; v < operands.size(); ++v) {
        const bool expected =
            ComparisonUnit::as_float(operands[v].first) <= ComparisonUnit::as_float(operands[v].second);
        ASSERT_EQ(results[v], expected ? "1" : "0")
            << hex32(operands[v].first) << " <= " << hex32(operands[v].second);
    }
}

// Box words in the lane's packing: the first bound in the lowest word.
std::string box_hex(const uint32_t (&box)[kCoordinates]) {
    std::string text;
    for (int c = kCoordinates - 1; c >= 0; --c) text += hex32(box[c]);
    return text;
}

TEST(CompareLaneRtl, Float32LaneEqualsTheModelsLaneHitThroughItsPipeline) {
    const std::vector<uint32_t> hard = hard_floats();
    std::mt19937 random(11);
    const auto pick = [&]() {
        // Mostly small ordinary values so that boxes often overlap; hard cases often.
        if (random() % 4 == 0) return hard[random() % hard.size()];
        return ComparisonUnit::as_bits(static_cast<float>(static_cast<int>(random() % 9) - 4));
    };
    std::vector<std::string> lines;
    std::vector<bool> expected;
    for (int v = 0; v < 4000; ++v) {
        uint32_t i[kCoordinates], j[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            i[c] = pick();
            j[c] = pick();
        }
        lines.push_back(box_hex(i) + box_hex(j));
        float fi[kCoordinates], fj[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            fi[c] = ComparisonUnit::as_float(i[c]);
            fj[c] = ComparisonUnit::as_float(j[c]);
        }
        expected.push_back(ComparisonUnit::lane_hit(fi, fj));
    }
    for (const char* latency : {"0", "2", "3"}) {
        Simulation sim;
        sim.write_vectors(lines);
        const std::vector<std::string> results =
            sim.run("tb_compare_lane",
                    {"models/comparison_unit/rtl/float_le.v", "models/comparison_unit/rtl/compare_lane.v"},
                    {{"LATENCY", latency}}, "+count=" + std::to_string(lines.size()));
        ASSERT_EQ(results.size(), lines.size()) << "latency " << latency;
        int hits = 0;
        for (std::size_t v = 0; v < lines.size(); ++v) {
            ASSERT_EQ(results[v], expected[v] ? "1" : "0") << "vector " << v << ", latency " << latency;
            hits += expected[v];
        }
        EXPECT_GT(hits, 40);  // the vectors exercise both outcomes
        EXPECT_GT(static_cast<int>(lines.size()) - hits, 1000);
    }
}

// The fixed-point lane (FLOAT=0) against the model's lane test in that
// format, at widths at the block RAM aspect boundaries and the full 32 bits.
// The model gets whole host words (it keeps the low K bits); the RTL, being
// K bits wide, gets those bits.
TEST(CompareLaneRtl, FixedPointLaneEqualsTheModelsLaneHitInThatFormat) {
    for (uint32_t width : {8u, 9u, 12u, 18u, 32u}) {
        const NumberFormat format = NumberFormat::fixed(width);
        const uint32_t top = format.word_mask();
        std::mt19937 random(13 + width);
        const auto pick = [&]() -> uint32_t {
            const uint32_t junk = static_cast<uint32_t>(random()) & ~top;  // bits the memories drop
            switch (random() % 3) {
                case 0: return junk | (random() % 6);          // small: equal bounds are frequent
                case 1: return junk | (top - random() % 6);    // at the top of the range
                default: return static_cast<uint32_t>(random());
            }
        };
        std::vector<std::string> lines;
        std::vector<bool> expected;
        for (int v = 0; v < 2000; ++v) {
            uint32_t i[kCoordinates], j[kCoordinates];
            for (uint32_t c = 0; c < kCoordinates; ++c) {
                i[c] = pick();
                j[c] = pick();
            }
            expected.push_back(ComparisonUnit::lane_hit(format, i, j));
            // {box_i, box_j}, coordinate 5 first, K bits each, as one hex number.
            std::vector<bool> bits;
            for (const uint32_t* box : {i, j}) {
                for (int c = kCoordinates - 1; c >= 0; --c) {
                    for (int b = static_cast<int>(width) - 1; b >= 0; --b) bits.push_back(((box[c] & top) >> b) & 1u);
                }
            }
            bits.insert(bits.begin(), (4 - bits.size() % 4) % 4, false);
            std::string text;
            for (std::size_t b = 0; b < bits.size(); b += 4) {
                text += "0123456789abcdef"[bits[b] * 8 + bits[b + 1] * 4 + bits[b + 2] * 2 + bits[b + 3]];
            }
            lines.push_back(text);
        }
        Simulation sim;
        sim.write_vectors(lines);
        const std::vector<std::string> results =
            sim.run("tb_compare_lane",
                    {"models/comparison_unit/rtl/float_le.v", "models/comparison_unit/rtl/compare_lane.v"},
                    {{"FLOAT", "0"}, {"WIDTH", std::to_string(width)}, {"LATENCY", "2"}},
                    "+count=" + std::to_string(lines.size()));
        ASSERT_EQ(results.size(), lines.size()) << format.name();
        int hits = 0;
        for (std::size_t v = 0; v < lines.size(); ++v) {
            ASSERT_EQ(results[v], expected[v] ? "1" : "0") << format.name() << " vector " << v;
            hits += expected[v];
        }
        EXPECT_GT(hits, 20) << format.name();  // both outcomes exercised
        EXPECT_GT(static_cast<int>(lines.size()) - hits, 500) << format.name();
    }
}

TEST(AddressGeneratorRtl, IssuesTheModelsAddressesCycleByCycle) {
    for (const uint32_t m : {1u, 2u, 3u, 8u}) {
        for (const uint32_t objects : {0u, 1u, 2u, 3u, 5u, 16u, 17u, 100u}) {
            Simulation sim;
            const std::vector<std::string> results = sim.run(
                "tb_address_generator", {"models/address_generator/rtl/address_generator.v"},
                {{"M", std::to_string(m)}}, "+objects=" + std::to_string(objects));
            AddressGenerator model(m);
            model.start(objects);
            std::vector<std::string> expected;
            for (; !model.exhausted(); model.advance()) {
                const PortWindow issue = model.current();
                const uint64_t mask = (uint64_t{1} << issue.valid_lanes) - 1;
                std::ostringstream line;
                line << std::hex << issue.row << ' ' << issue.first_column << ' ' << mask;
                expected.push_back(line.str());
            }
            ASSERT_EQ(results, expected) << "m = " << m << ", N = " << objects;
            EXPECT_EQ(results.size(), AddressGenerator::sweep_cycles(objects, m));
        }
    }
}

TEST(PairCollectorRtl, PassesEveryPairOnInRowThenColumnOrderUnderBackPressure) {
    for (const uint32_t m : {1u, 2u, 4u}) {
        const uint32_t lanes = 2 * m - 1;
        std::mt19937 random(17 + m);
        std::vector<std::string> lines;
        std::vector<std::string> expected;
        uint32_t row = 0;
        for (int v = 0; v < 600; ++v) {
            const uint32_t hits = random() & ((1u << lanes) - 1);
            const uint32_t first = row + 1 + (v % 5) * lanes;
            const bool drain = random() % 4 != 0;  // the pair buffer refuses a quarter of the cycles
            for (uint32_t k = 0; k < lanes; ++k) {
                if ((hits >> k) & 1) {
                    std::ostringstream pair;
                    pair << std::hex << row << ' ' << first + k;
                    expected.push_back(pair.str());
                }
            }
            // {drain, hits, row, first}: 1 + lanes + 16 + 16 bits.
            const Word128 word = (static_cast<Word128>(drain) << (lanes + 32)) | (static_cast<Word128>(hits) << 32) |
                                 (static_cast<Word128>(row) << 16) | first;
            char text[40];
            std::snprintf(text, sizeof text, "%llx%016llx", static_cast<unsigned long long>(word >> 64),
                          static_cast<unsigned long long>(word));
            lines.push_back(text);
            if (v % 5 == 4) ++row;
        }
        Simulation sim;
        sim.write_vectors(lines);
        const std::vector<std::string> results =
            sim.run("tb_pair_collector", {"models/pair_collector/rtl/pair_collector.v"},
                    {{"M", std::to_string(m)}, {"DEPTH", "16"}, {"DISTRIBUTED", m == 2 ? "1" : "0"}},
                    "+count=" + std::to_string(lines.size()));
        ASSERT_EQ(results, expected) << "m = " << m;
    }
}


// ---------------------------------------------------------------------------
// The whole board (models/board/rtl/collision_board_top.v) against BoardCore
// with the clocked engine. A host script (writes, reads, waits for the board
// to stop) is applied to the model as it is written; the testbench runs the
// same script on the RTL and every read must return the model's word: the
// pairs in board order through every overflow pause, CYCLES, STALLS,
// TOTAL_PAIRS, PAIR_COUNT, STATUS and ERROR_CAUSE.

// One board: the RTL's parameters and the model's configuration from them.
struct TopBoard {
    uint32_t m = 2;
    uint32_t address_bits = 9;    // capacity 2^address_bits boxes
    uint32_t fixed_bits = 0;      // 0: float32
    uint32_t compare_latency = 2;
    uint32_t fifo_depth = 16;
    uint32_t buffer_depth = 64;
    uint32_t tile_boxes = 0;
    uint32_t tile_latency = 2;

    uint32_t capacity() const { return 1u << address_bits; }
    BoardConfig config() const {
        BoardConfig c;
        c.m = m;
        c.format = fixed_bits == 0 ? NumberFormat::float32() : NumberFormat::fixed(fixed_bits);
        c.compare.latency_cycles = compare_latency;
        c.collector.fifo_depth = fifo_depth;
        c.collector.buffer_depth = buffer_depth;
        c.tiles.boxes = tile_boxes;
        c.tiles.load_latency_cycles = tile_latency;
        c.tiles.cycles_per_box = 1;
        return c;
    }
    std::vector<std::pair<std::string, std::string>> parameters() const {
        return {{"M", std::to_string(m)},
                {"AW", std::to_string(address_bits)},
                {"FLOAT", fixed_bits == 0 ? "1" : "0"},
                {"WIDTH", std::to_string(fixed_bits == 0 ? 32 : fixed_bits)},
                {"COMPARE_LATENCY", std::to_string(compare_latency)},
                {"FIFO_DEPTH", std::to_string(fifo_depth)},
                {"BUFFER_DEPTH", std::to_string(buffer_depth)},
                {"TILE_BOXES", std::to_string(tile_boxes)},
                {"TILE_LATENCY", std::to_string(tile_latency)}};
    }
};

// Boxes as the host writes them: six words each, in Coordinate order.
using Boxes = std::vector<std::array<uint32_t, kCoordinates>>;

// n boxes in a cube of side `side` with half-extents in [0.5, 1.5), some
// touching exactly, some at -0 / +0 (float32); or the same scaled by 100 in
// K-bit integers, with junk above bit K that the memories drop. Boxes 0-7,
// 64-71, ... sit in a corner where all overlap: runs of hits on every lane
// that fill the FIFO and hold the pipeline.
Boxes random_boxes(uint32_t n, double side, uint32_t fixed_bits, uint32_t seed) {
    std::mt19937 random(seed);
    const double scale = fixed_bits == 0 ? 1.0 : 100.0;
    std::uniform_real_distribution<double> where(0.0, side * scale), half(0.5 * scale, 1.5 * scale);
    Boxes boxes(n);
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t axis = 0; axis < 3; ++axis) {
            double lo = i % 64 < 8 ? where(random) / side : where(random), hi = 0;
            if (i > 0 && random() % 8 == 0) {
                // touch the previous box's max on this axis
                lo = fixed_bits == 0 ? ComparisonUnit::as_float(boxes[i - 1][axis + 3])
                                     : static_cast<double>(boxes[i - 1][axis + 3]);
            }
            hi = lo + 2 * half(random);
            if (fixed_bits == 0) {
                float flo = static_cast<float>(lo), fhi = static_cast<float>(hi);
                if (random() % 16 == 0) { flo = -0.0f; fhi = std::max(fhi, 0.5f); }
                boxes[i][axis] = ComparisonUnit::as_bits(flo);
                boxes[i][axis + 3] = ComparisonUnit::as_bits(fhi);
            } else {
                const uint32_t top = fixed_bits == 32 ? ~0u : (1u << fixed_bits) - 1;
                const uint32_t junk = static_cast<uint32_t>(random()) & ~top;  // bits the memories drop
                const auto code = [&](double v) { return static_cast<uint32_t>(std::min<double>(v, top)); };
                boxes[i][axis] = junk | code(std::floor(lo));
                boxes[i][axis + 3] = junk | code(std::ceil(hi));
            }
        }
    }
    return boxes;
}

// The script and what every read must return, built against the model.
class HostScript {
public:
    explicit HostScript(const TopBoard& board) : core_(board.config(), board.capacity(), Fidelity::kCycle) {}

    BoardCore& core() { return core_; }
    void write(uint32_t address, uint32_t data) {
        add(1, address, data);
        const uint32_t region = address >> 24, offset = address & 0xFFFFFF;
        if (region == 0) {
            core_.write_register(offset, data);
        } else if (region >= 1 && region <= 6) {
            core_.write_coordinate(static_cast<Coordinate>(region - 1), offset / 4, data);
        } else if (region == 9) {
            unsigned char bytes[4];
            std::memcpy(bytes, &data, 4);
            core_.write_delta(bytes, 1);
        }
    }
    uint32_t read(uint32_t address) {
        add(2, address, 0);
        uint32_t value = 0;
        const uint32_t region = address >> 24, offset = address & 0xFFFFFF;
        if (region == 0) {
            if (!core_.read_register(offset, value)) value = 0;
        } else if (region == 7) {
            unsigned char bytes[4];
            core_.copy_window_words(offset / 4, 1, bytes);
            std::memcpy(&value, bytes, 4);
        }
        expected_.push_back(hex32(value));
        return value;
    }
    void wait() {
        add(3, 0, 0);
        if (core_.running()) {
            longest_segment_ = std::max(longest_segment_, core_.segment_edges());
            core_.advance_to(core_.segment_edges());
        }
    }
    void write_register(uint32_t offset, uint32_t data) { write(offset, data); }
    uint32_t read_register(uint32_t offset) { return read(offset); }
    void write_box(uint32_t i, const std::array<uint32_t, kCoordinates>& box) {
        for (uint32_t c = 0; c < kCoordinates; ++c) write(0x0100'0000u * (c + 1) + 4 * i, box[c]);
    }
    void write_delta_record(uint32_t i, const std::array<uint32_t, kCoordinates>& box) {
        write(0x0900'0000u, i);
        for (uint32_t c = 0; c < kCoordinates; ++c) write(0x0900'0000u, box[c]);
    }

    // One sweep as a driver runs it: START, wait, read the buffer and RESUME
    // on every overflow, read the buffer and the counters when done.
    // Returns the overflow pauses.
    uint32_t sweep(uint32_t objects) {
        using R = ControlRegisters;
        write_register(R::kObjectCount, objects);
        write_register(R::kControl, R::kStart);
        uint32_t pauses = 0;
        for (;;) {
            wait();
            const uint32_t status = read_register(R::kStatus);
            const uint32_t words = read_register(R::kPairWords);
            const uint32_t pairs = read_register(R::kPairCount);
            EXPECT_EQ(words, 2 * pairs);
            for (uint32_t w = 0; w < words; ++w) read(0x0700'0000u + 4 * w);
            if ((status & R::kOverflow) == 0) break;
            ++pauses;
            write_register(R::kControl, R::kResume);
        }
        for (uint32_t offset : {R::kStatus, R::kCyclesLo, R::kCyclesHi, R::kStallsLo, R::kStallsHi,
                                R::kTotalPairsLo, R::kTotalPairsHi, R::kErrorCause, R::kDeltaRecords}) {
            read_register(offset);
        }
        write_register(R::kControl, R::kAcknowledge);
        return pauses;
    }

    // The testbench's results against the model's.
    void run_and_compare(const TopBoard& board, const std::string& what) {
        add(0, 0, 0);
        // A board that never stops fails in twice the model's longest segment.
        auto parameters = board.parameters();
        parameters.emplace_back("MAX_WAIT", std::to_string(2 * longest_segment_ + 1000));
        Simulation sim;
        sim.write_vectors(lines_, "commands.txt");
        const std::vector<std::string> results =
            sim.run("tb_board_top",
                    {"models/board/rtl/collision_board_top.v", "models/board/rtl/board_host.v", "models/board/rtl/board_ram.v",
                     "models/board/rtl/tile_walker.v", "models/address_generator/rtl/address_generator.v",
                     "models/comparison_unit/rtl/float_le.v", "models/comparison_unit/rtl/compare_lane.v",
                     "models/pair_collector/rtl/pair_collector.v", "models/control_registers/rtl/board_control.v"},
                    parameters, "");
        if (std::getenv("CDVP_RTL_KEEP") != nullptr) {
            std::ofstream keep(sim.dir() + "/expected.txt");
            for (const std::string& line : expected_) keep << line << '\n';
        }
        ASSERT_EQ(results.size(), expected_.size()) << what;
        for (std::size_t k = 0; k < results.size(); ++k) {
            ASSERT_EQ(results[k], expected_[k]) << what << ": read " << k << " of " << results.size()
                                                << " (address " << std::hex << read_addresses_[k] << ")";
        }
    }

private:
    void add(int op, uint32_t address, uint32_t data) {
        std::ostringstream line;
        line << std::hex << op << ' ' << address << ' ' << data;
        lines_.push_back(line.str());
        if (op == 2) read_addresses_.push_back(address);
    }
    BoardCore core_;
    uint64_t longest_segment_ = 0;
    std::vector<std::string> lines_;
    std::vector<std::string> expected_;
    std::vector<uint32_t> read_addresses_;
};

// The board's identity registers, then the scene's sweeps at the given sizes.
struct TopScene {
    TopBoard board;
    std::vector<uint32_t> sweeps;  // object counts, swept in turn over one scene
    double side;                   // the scene's cube
    bool delta = false;            // boxes written as delta records
};

void run_top_scene(const TopScene& scene, uint32_t seed, bool expect_stalls, bool expect_pauses) {
    using R = ControlRegisters;
    const TopBoard& board = scene.board;
    std::ostringstream what;
    what << "m=" << board.m << " AW=" << board.address_bits << " fixed=" << board.fixed_bits
         << " Lc=" << board.compare_latency << " fifo=" << board.fifo_depth << " buffer=" << board.buffer_depth
         << " tile=" << board.tile_boxes;
    HostScript script(board);
    for (uint32_t offset : {R::kId, R::kParallelism, R::kCapacity, R::kPairBufferDepth, R::kFormat, R::kTileBoxes,
                            R::kTileTiming, R::kStatus, R::kBoxBanks, R::kHostBank, R::kPairBank}) {
        script.read_register(offset);
    }
    const uint32_t most = *std::max_element(scene.sweeps.begin(), scene.sweeps.end());
    const Boxes boxes = random_boxes(most, scene.side, board.fixed_bits, seed);
    for (uint32_t i = 0; i < most; ++i) {
        if (scene.delta) script.write_delta_record(i, boxes[i]);
        else script.write_box(i, boxes[i]);
    }
    uint64_t stalls = 0, pauses = 0, pairs = 0;
    for (const uint32_t n : scene.sweeps) {
        pauses += script.sweep(n);
        const SweepCounters counters = script.core().counters();
        stalls += counters.stalls;
        pairs += counters.total_pairs;
        // The model's own account: S + L edges and the stalls.
        EXPECT_EQ(counters.cycles, board.config().sweep_cycles(n) + board.config().pipeline_latency() + counters.stalls)
            << what.str() << " N=" << n;
    }
    EXPECT_GT(pairs, 0u) << what.str();
    if (expect_stalls) {
        EXPECT_GT(stalls, 0u) << what.str();
    }
    if (expect_pauses) {
        EXPECT_GT(pauses, 0u) << what.str();
    }
    script.run_and_compare(board, what.str());
}

TEST(BoardTopRtl, OneLaneFloat32MatchesTheModel) {
    TopScene scene;
    scene.board = {1, 9, 0, 2, 512, 512, 0, 2};
    scene.sweeps = {0, 1, 2, 3, 200};
    scene.side = 25;
    run_top_scene(scene, 101, false, false);
}

TEST(BoardTopRtl, TwoBlockRamsDeepWithFifoStallsAndOverflowPauses) {
    TopScene scene;
    scene.board = {2, 10, 0, 2, 3, 24, 0, 2};  // the smallest FIFO (2m-1) and a small buffer
    scene.sweeps = {600};                       // across the 512-box block RAM border
    scene.side = 45;
    run_top_scene(scene, 102, true, true);
}

TEST(BoardTopRtl, ThreeLanePairsFixed16WithDeltaRecords) {
    TopScene scene;
    scene.board = {3, 9, 16, 1, 8, 40, 0, 2};
    scene.sweeps = {512, 37};   // the full capacity, then a few
    scene.side = 40;
    scene.delta = true;
    run_top_scene(scene, 103, true, true);
}

TEST(BoardTopRtl, EightLanePairsFloat32CombinationalCompare) {
    TopScene scene;
    scene.board = {8, 10, 0, 0, 16, 100, 0, 2};
    scene.sweeps = {513, 700};  // one past a block RAM, and well into the second
    scene.side = 45;
    run_top_scene(scene, 104, true, true);
}

TEST(BoardTopRtl, TiledSceneFromSsramMatchesTheModel) {
    TopScene scene;
    scene.board = {2, 10, 0, 2, 6, 32, 64, 2};
    scene.sweeps = {300, 129, 64, 1};  // a partial last tile, a one-box last tile, one tile, none
    scene.side = 30;
    run_top_scene(scene, 105, true, true);
}

TEST(BoardTopRtl, TiledFixed12WithoutSsramLatencyMatchesTheModel) {
    TopScene scene;
    scene.board = {3, 9, 12, 0, 5, 16, 32, 0};
    scene.sweeps = {161, 70};
    scene.side = 20;
    run_top_scene(scene, 106, true, true);
}

TEST(BoardTopRtl, TilesOfOneAndTwoBoxesMatchTheModel) {
    // One-box tiles: every diagonal block but the last is empty and left in
    // the slot it is entered; two-box tiles: every diagonal block one window.
    for (const uint32_t tile : {1u, 2u}) {
        TopScene scene;
        scene.board = {2, 6, 0, 2, 6, 32, tile, 2};
        scene.sweeps = {37, 2, 3};
        scene.side = 6;
        run_top_scene(scene, 107 + tile, false, false);
    }
}

// The tile walker rebuilt for the clock against the walker as first written
// (tests/rtl/tile_walker_reference.v), clock for clock, under random slot
// patterns, on every object count up to three tiles and random ones to 255:
// lanes from one to 63, tiles from two boxes to 64, SSRAM latencies 0 to 8.
TEST(TileWalkerRtl, SlotForSlotTheWalkerAsFirstWritten) {
    struct Shape {
        uint32_t m, tile, latency;
    };
    for (const Shape& shape : std::vector<Shape>{{1, 3, 3}, {2, 2, 1}, {2, 5, 2}, {3, 8, 0}, {8, 16, 2},
                                                 {4, 64, 8}, {24, 64, 2}, {32, 4, 1}}) {
        uint32_t address_bits = 1;
        while ((1u << address_bits) < shape.tile) ++address_bits;
        const Simulation sim;
        const std::vector<std::string> lines =
            sim.run("tb_tile_walker", {"models/board/rtl/tile_walker.v", "tests/rtl/tile_walker_reference.v"},
                    {{"M", std::to_string(shape.m)},
                     {"AW", "8"},
                     {"T", std::to_string(shape.tile)},
                     {"TAW", std::to_string(address_bits)},
                     {"LAT", std::to_string(shape.latency)}},
                    "+seed=" + std::to_string(shape.m * 100 + shape.tile) +
                        " +max=" + std::to_string(std::min(3 * shape.tile + 3, 40u)) + " +extra=4");
        const std::string what = "m=" + std::to_string(shape.m) + " T=" + std::to_string(shape.tile) +
                                 " LAT=" + std::to_string(shape.latency);
        ASSERT_FALSE(lines.empty()) << what;
        unsigned long windows = 0, lands = 0, reads = 0, mismatches = 1;
        ASSERT_EQ(std::sscanf(lines.back().c_str(), "windows %lu lands %lu reads %lu mismatches %lu", &windows,
                              &lands, &reads, &mismatches),
                  4)
            << what << ": " << lines.back();
        EXPECT_EQ(mismatches, 0u) << what << ": " << lines.front();
        EXPECT_GT(windows, 1000u) << what;
        EXPECT_GT(lands, 100u) << what;
        EXPECT_EQ(lands, reads) << what;  // every word read lands in a tile buffer
    }
}

// Refused commands set ERROR with the model's cause and the sweep goes on;
// ABORT clears them.
TEST(BoardTopRtl, ErrorCausesAndAbortMatchTheModel) {
    using R = ControlRegisters;
    TopBoard board{2, 9, 0, 2, 8, 32, 0, 2};
    HostScript script(board);
    const Boxes boxes = random_boxes(300, 20, 0, 107);
    for (uint32_t i = 0; i < 300; ++i) script.write_box(i, boxes[i]);
    const auto status = [&] {
        script.read_register(R::kStatus);
        script.read_register(R::kErrorCause);
    };
    script.write_register(R::kControl, R::kResume);  // not paused
    status();
    script.write_register(R::kObjectCount, 513);     // above the capacity
    script.write_register(R::kControl, R::kStart);
    status();
    script.write_register(R::kControl, R::kAbort);
    status();
    script.write_register(R::kPairFormat, 7);        // no such format
    status();
    script.write(0x0900'0000u, 3);                   // a delta record begun
    script.write_register(R::kObjectCount, 300);
    script.write_register(R::kControl, R::kStart);   // refused: the record is incomplete
    status();
    for (uint32_t c = 0; c < kCoordinates; ++c) script.write(0x0900'0000u, boxes[3][c]);
    script.write(0x0900'0000u, 600);                 // a record past the capacity
    for (uint32_t c = 0; c < kCoordinates; ++c) script.write(0x0900'0000u, 0);
    status();
    script.read_register(R::kDeltaRecords);
    script.write_register(R::kControl, R::kAbort);
    script.write_register(R::kControl, R::kStart);   // runs
    script.write_box(5, boxes[5]);                   // refused while busy
    script.write_register(R::kObjectCount, 3);       // refused while busy
    script.write_register(R::kControl, R::kStart);   // refused while busy
    script.read_register(R::kObjectCount);
    status();
    script.wait();
    status();
    script.read_register(R::kPairCount);
    script.write_register(R::kControl, R::kResume);  // paused: accepted
    script.wait();
    script.write_register(R::kControl, R::kAbort);   // the board stops, the counters stay
    status();
    script.read_register(R::kPairCount);
    script.read_register(R::kTotalPairsLo);
    script.run_and_compare(board, "errors");
}

// STATUS's INTERRUPT bit follows the line: set by done, an overflow pause or
// an error, cleared by ACKNOWLEDGE, START, RESUME and ABORT.
TEST(BoardTopRtl, InterruptBitFollowsTheLineUntilAcknowledge) {
    using R = ControlRegisters;
    TopBoard board{2, 9, 0, 2, 8, 32, 0, 2};
    HostScript script(board);
    const Boxes boxes = random_boxes(300, 20, 0, 108);
    for (uint32_t i = 0; i < 300; ++i) script.write_box(i, boxes[i]);
    const auto interrupt = [&] { return (script.read_register(R::kStatus) & R::kInterrupt) != 0; };
    EXPECT_FALSE(interrupt());                        // after reset
    script.write_register(R::kObjectCount, 300);
    script.write_register(R::kControl, R::kStart);
    EXPECT_FALSE(interrupt());                        // sweeping
    script.wait();                                    // an overflow pause
    ASSERT_NE(script.read_register(R::kStatus) & R::kOverflow, 0u);
    EXPECT_TRUE(interrupt());
    script.write_register(R::kControl, R::kAcknowledge);
    EXPECT_FALSE(interrupt());                        // still paused, the line low
    script.write_register(R::kControl, R::kResume);
    uint32_t status = 0;
    for (;;) {                                        // RESUME through every pause to done
        script.wait();
        status = script.read_register(R::kStatus);
        EXPECT_NE(status & R::kInterrupt, 0u);
        if ((status & R::kOverflow) == 0) break;
        script.write_register(R::kControl, R::kResume);
        EXPECT_FALSE(interrupt());                    // RESUME drops the line
    }
    EXPECT_NE(status & R::kDone, 0u);
    script.write_register(R::kControl, R::kAcknowledge);
    EXPECT_FALSE(interrupt());                        // done, the line low
    script.write_register(R::kControl, R::kResume);   // refused: an error raises the line
    EXPECT_TRUE(interrupt());
    script.read_register(R::kErrorCause);
    script.write_register(R::kControl, R::kAcknowledge);
    EXPECT_FALSE(interrupt());                        // ERROR stays, the line drops
    script.write_register(R::kPairBank, 5);           // refused: the line rises again
    EXPECT_TRUE(interrupt());
    script.write_register(R::kControl, R::kAbort);
    EXPECT_FALSE(interrupt());
    script.run_and_compare(board, "interrupt");
}

// PAIR_BANK: 1 shows the previous pair buffer, which a one-bank board never
// fills (PAIR_COUNT 0); 0 shows the sweep's pairs again; 2 is refused with
// kBadPairBank and leaves the bank as it was.
TEST(BoardTopRtl, PairBankShowsTheEmptyPreviousBufferOnOneBank) {
    using R = ControlRegisters;
    TopBoard board{2, 9, 0, 2, 16, 512, 0, 2};
    HostScript script(board);
    const Boxes boxes = random_boxes(100, 20, 0, 109);
    for (uint32_t i = 0; i < 100; ++i) script.write_box(i, boxes[i]);
    for (uint32_t offset : {R::kBoxBanks, R::kHostBank, R::kPairBank}) script.read_register(offset);
    script.sweep(100);                                // the pairs now in the current buffer
    const uint32_t pairs = script.read_register(R::kPairCount);
    EXPECT_GT(pairs, 0u);
    script.write_register(R::kPairBank, R::kPreviousPairs);
    EXPECT_EQ(script.read_register(R::kPairBank), 1u);
    EXPECT_EQ(script.read_register(R::kPairCount), 0u);
    EXPECT_EQ(script.read_register(R::kPairWords), 0u);
    script.read_register(R::kHostBank);
    EXPECT_EQ(script.read_register(R::kStatus) & R::kError, 0u);
    script.write_register(R::kPairBank, 2);           // no such bank
    EXPECT_NE(script.read_register(R::kStatus) & R::kError, 0u);
    EXPECT_EQ(script.read_register(R::kErrorCause), uint32_t{R::kBadPairBank});
    EXPECT_EQ(script.read_register(R::kPairBank), 1u);
    script.write_register(R::kPairBank, R::kCurrentPairs);
    EXPECT_EQ(script.read_register(R::kPairCount), pairs);
    for (uint32_t w = 0; w < 2 * pairs; ++w) script.read(0x0700'0000u + 4 * w);
    // A sweep with PAIR_BANK at 1 runs as any other; its pairs show at 0.
    script.write_register(R::kControl, R::kAbort);
    script.write_register(R::kPairBank, R::kPreviousPairs);
    script.write_register(R::kObjectCount, 60);
    script.write_register(R::kControl, R::kStart);
    script.write_register(R::kPairBank, R::kPreviousPairs);  // accepted while busy
    script.read_register(R::kStatus);
    script.wait();
    script.read_register(R::kStatus);
    EXPECT_EQ(script.read_register(R::kPairCount), 0u);
    script.write_register(R::kPairBank, R::kCurrentPairs);
    const uint32_t later = script.read_register(R::kPairCount);
    EXPECT_GT(later, 0u);
    for (uint32_t w = 0; w < 2 * later; ++w) script.read(0x0700'0000u + 4 * w);
    script.read_register(R::kTotalPairsLo);
    script.run_and_compare(board, "pair bank");
}

}  // namespace
}  // namespace cdvp
