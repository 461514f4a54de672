// The driver is host software on its own: here it runs against a port that
// reaches a plain C++ board directly, with no SystemC kernel at all.
#include "platform/driver/board_driver.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "models/address_generator/address_generator.h"
#include "models/board/board_core.h"
#include "sw/baselines/brute_force.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

// A host whose bus takes a fixed time per access, with the board behind it
// clocked from that time; PIO and polling only (no DMA engine, no interrupt).
class DirectPort : public HostPort {
public:
    DirectPort(BoardCore& board, SimTime period, SimTime access_time)
        : board_(board), period_(period), access_(access_time), memory_(1 << 20) {}

    std::string read(uint64_t address, void* data, uint32_t length) override {
        return access(address, static_cast<unsigned char*>(data), length, false);
    }
    std::string write(uint64_t address, const void* data, uint32_t length) override {
        return access(address, static_cast<unsigned char*>(const_cast<void*>(data)), length, true);
    }
    unsigned char* memory(uint64_t address) override { return memory_.data() + address; }
    uint64_t memory_size() const override { return memory_.size(); }
    SimTime now() const override { return now_; }
    void wait(SimTime duration) override { now_ += duration; }
    void wait_for_interrupt(SimTime timeout) override { now_ += timeout; }  // never comes: no interrupt line here

private:
    std::string access(uint64_t address, unsigned char* data, uint32_t length, bool write) {
        if (board_.running()) board_.advance_to((now_ - segment_start_) / period_);
        const uint64_t segments = board_.segments_started();
        std::string error;
        for (uint32_t k = 0; k < length && error.empty(); k += 4) error = word(address + k, data + k, write);
        if (board_.segments_started() != segments) segment_start_ = now_;
        now_ += access_;
        return error;
    }
    std::string word(uint64_t address, unsigned char* data, bool write) {
        uint32_t value = 0;
        if (write) std::memcpy(&value, data, 4);
        if (address < address_map::kRegistersSize) {
            const auto offset = static_cast<uint32_t>(address);
            if (write) return board_.write_register(offset, value) == RegisterResult::kDone ? "" : "refused";
            if (!board_.read_register(offset, value)) return "unmapped";
        } else if (address >= address_map::kPairBuffer) {
            const uint64_t k = (address - address_map::kPairBuffer) / 4;
            if (write || k / 2 >= board_.buffered_pairs()) return "unmapped";
            const IndexPair& p = board_.buffered_pair(static_cast<uint32_t>(k / 2));
            value = k % 2 == 0 ? p.first : p.second;
        } else {
            const uint64_t offset = address - address_map::kCoordinateBase;
            const auto c = static_cast<Coordinate>(offset / address_map::kWindowSize);
            const auto i = static_cast<uint32_t>(offset % address_map::kWindowSize / 4);
            if (!write) return "write-only here";
            if (board_.write_coordinate(c, i, value) != RegisterResult::kDone) return "refused";
        }
        if (!write) std::memcpy(data, &value, 4);
        return "";
    }

    BoardCore& board_;
    SimTime period_, access_;
    std::vector<unsigned char> memory_;
    SimTime now_ = 0, segment_start_ = 0;
};

TEST(DriverWithoutKernel, RunsFramesThroughOverflowPausesByPioAndPolling) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 40;
    BoardCore board(config, 300);
    const SimTime period = fs_from_ns(15.0), access = fs_from_ns(100.0);
    DirectPort port(board, period, access);
    DriverConfig driver_config;
    driver_config.transfer = Transfer::kPio;
    driver_config.wait = WaitMode::kPoll;
    BoardDriver driver(port, period, driver_config, nullptr);
    driver.open();
    EXPECT_EQ(driver.capacity(), 300u);

    std::mt19937 rng(4);
    std::vector<FloatBox> boxes;
    for (int frame = 0; frame < 3; ++frame) {
        boxes = testing::random_boxes(300, 12.0f, 3.0f, rng);
        PairList pairs;
        const FramePhases phases = driver.run_frame(boxes, pairs);
        const PairList expected = reference_pairs(boxes);
        ASSERT_GT(expected.size(), 40u) << "the scene must overflow the pair buffer";
        EXPECT_EQ(sorted(pairs), expected);
        EXPECT_EQ(phases.overflow_pauses, (expected.size() - 1) / 40);
        EXPECT_EQ(phases.compute_cycles,
                  AddressGenerator::sweep_cycles(300, config.m) + config.pipeline_latency() + phases.stall_cycles);
        EXPECT_NEAR(phases.upload_ns + phases.start_ns + phases.compute_ns + phases.irq_ns + phases.readback_ns +
                        phases.driver_ns,
                    phases.total_ns, 1e-6 * phases.total_ns);
        // Polling notices the board within one poll (a status read and the gap of one board period).
        EXPECT_LE(phases.irq_ns, (phases.overflow_pauses + 1) * (100.0 + 15.0) + 1e-6);
    }
    for (uint32_t i = 0; i < 300; ++i) {
        ASSERT_EQ(ComparisonUnit::as_float(board.read_coordinate(kMaxZ, i)), boxes[i].max[2]) << "box " << i;
    }
}

// The read-back holds the pair budget for every engine: the clocked board
// pauses at each full buffer, and the driver refuses the buffer that would
// take the frame past its budget, with no pairs handed out.
TEST(DriverWithoutKernel, RefusesTheBufferThatWouldPassThePairBudget) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 40;
    BoardCore board(config, 300);
    const SimTime period = fs_from_ns(15.0);
    DirectPort port(board, period, fs_from_ns(100.0));
    std::mt19937 rng(4);
    const std::vector<FloatBox> boxes = testing::random_boxes(300, 12.0f, 3.0f, rng);
    const uint64_t all = reference_pairs(boxes).size();
    ASSERT_GT(all, 200u);
    DriverConfig driver_config;
    driver_config.transfer = Transfer::kPio;
    driver_config.wait = WaitMode::kPoll;
    driver_config.pair_budget = PairBudget(100);
    BoardDriver driver(port, period, driver_config, nullptr);
    driver.open();
    PairList pairs;
    try {
        driver.run_frame(boxes, pairs);
        ADD_FAILURE() << "a frame of " << all << " pairs passed a budget of 100";
    } catch (const PairBudgetExceeded& e) {
        EXPECT_EQ(e.found(), 120u) << "three full buffers of 40";
        EXPECT_EQ(e.budget(), 100u);
    }
    EXPECT_TRUE(pairs.empty());
}

}  // namespace
}  // namespace cdvp
