// The RTL behind the resource model computes what the C++ model computes:
// each Verilog piece runs under Icarus Verilog on vectors from these tests
// and its outputs are compared with the model's. Hard numeric cases (NaN,
// -0, infinities, denormals, equal bounds) are in every comparator vector set.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
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
#include "models/comparison_unit/comparison_unit.h"

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
    ~Simulation() { std::system(("rm -rf '" + dir_ + "'").c_str()); }

    void write_vectors(const std::vector<std::string>& lines) const {
        std::ofstream out(dir_ + "/vectors.hex");
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

}  // namespace
}  // namespace cdvp
