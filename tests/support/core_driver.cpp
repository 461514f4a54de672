#include "tests/support/core_driver.h"

#include <cstring>
#include <stdexcept>
#include <string>

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

std::vector<std::vector<FloatBox>> moving_frames(uint32_t n, std::mt19937& rng, float extent, int frames, bool rotate) {
    std::vector<std::vector<FloatBox>> out{random_boxes(n, extent, 2.5f, rng)};
    std::uniform_real_distribution<float> step(-0.3f, 0.3f);
    for (int f = 1; f < frames; ++f) {
        std::vector<FloatBox> next = out.back();
        for (uint32_t i = rotate ? f % 5 : 0; i < n; i += 5) {
            const float d = step(rng);
            for (int a = 0; a < 3; ++a) next[i].min[a] += d, next[i].max[a] += d;
        }
        if (f == 3) next.push_back(FloatBox{{1, 1, 1}, {2, 2, 2}});
        out.push_back(next);
    }
    return out;
}

uint32_t changed_boxes(const std::vector<FloatBox>& before, const std::vector<FloatBox>& now) {
    uint32_t count = 0;
    for (std::size_t i = 0; i < now.size(); ++i) {
        count += i >= before.size() || std::memcmp(&before[i], &now[i], sizeof(FloatBox)) != 0;
    }
    return count;
}

uint32_t read_register(BoardCore& core, uint32_t offset) {
    uint32_t value = 0;
    if (!core.read_register(offset, value)) throw std::runtime_error("no register at " + std::to_string(offset));
    return value;
}

CoordinateStore float32_store(const std::vector<FloatBox>& boxes) {
    CoordinateStore store;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (const FloatBox& b : boxes) store[c].push_back(ComparisonUnit::as_bits(c < 3 ? b.min[c] : b.max[c - 3]));
    }
    return store;
}

}  // namespace cdvp::testing
