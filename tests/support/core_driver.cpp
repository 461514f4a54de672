#include "tests/support/core_driver.h"

#include <stdexcept>

namespace cdvp::testing {

namespace {
void drain(BoardCore& core, PairList& out) {
    for (uint32_t k = 0; k < core.buffered_pairs(); ++k) out.push_back(core.buffered_pair(k));
}
}  // namespace

CoreRun run_core(BoardCore& core, const std::vector<FloatBox>& boxes) {
    const auto n = static_cast<uint32_t>(boxes.size());
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            const float v = c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3];
            if (core.write_coordinate(static_cast<Coordinate>(c), i, ComparisonUnit::as_bits(v)) != RegisterResult::kDone) {
                throw std::runtime_error("coordinate write refused");
            }
        }
    }
    core.write_register(ControlRegisters::kObjectCount, n);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    CoreRun run;
    while (core.phase() != SweepState::kDone) {
        if (core.phase() == SweepState::kPaused) {
            drain(core, run.pairs);
            ++run.pauses;
            core.write_register(ControlRegisters::kControl, ControlRegisters::kResume);
        } else if (core.running()) {
            core.step();
        } else {
            throw std::runtime_error("board neither running, paused nor done");
        }
    }
    drain(core, run.pairs);
    run.cycles = core.counters().cycles;
    run.stalls = core.counters().stalls;
    return run;
}

std::vector<FloatBox> random_boxes(std::size_t n, float extent, float size, std::mt19937& rng) {
    std::uniform_real_distribution<float> corner(0.0f, extent), side(0.0f, size);
    std::vector<FloatBox> boxes(n);
    for (FloatBox& b : boxes) {
        for (int a = 0; a < 3; ++a) {
            b.min[a] = corner(rng);
            b.max[a] = b.min[a] + side(rng);
        }
    }
    return boxes;
}

}  // namespace cdvp::testing
