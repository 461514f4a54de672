// libFuzzer target: the board preset loader (platform/settings/board_preset.h).
//
// Each input is written to an in-memory file (memfd) that the loader opens by
// its /proc/self/fd path, so nothing is left on disk. Invariants, each a
// crash when broken:
//  - no sanitizer report, no exception other than cdvp::InputError;
//  - a rejection is one line that starts with the preset's path;
//  - an accepted preset gives every time finite, non-negative and at most
//    kMaxOperationNs for one operation (a bus access, a DMA, an interrupt, a
//    host cost), and positive finite clocks: nothing overflows simulated time.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "platform/settings/board_preset.h"
#include "sw/scene/scene.h"

namespace {

// 1000 s: no single operation of a real board or host comes near it.
constexpr double kMaxOperationNs = 1e12;
// The largest DMA the checks time: 1 MiB.
constexpr uint64_t kDmaBytes = 1u << 20;

int preset_fd = -1;
std::string preset_path;

[[noreturn]] void violated(const std::string& what) {
    std::fprintf(stderr, "preset_fuzzer: invariant violated: %s\n", what.c_str());
    std::abort();
}

std::string shortest(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

void write_preset(const uint8_t* data, std::size_t size) {
    if (ftruncate(preset_fd, 0) != 0) violated(std::string("ftruncate: ") + std::strerror(errno));
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = pwrite(preset_fd, data + done, size - done, static_cast<off_t>(done));
        if (n <= 0) violated(std::string("pwrite: ") + std::strerror(errno));
        done += static_cast<std::size_t>(n);
    }
}

void check_time(const char* what, double ns) {
    if (!(std::isfinite(ns) && ns >= 0 && ns <= kMaxOperationNs)) {
        violated(std::string("accepted preset gives ") + what + " = " + shortest(ns) +
                 " ns; expected finite, >= 0 and <= 1e12");
    }
}

void check_positive(const char* what, double value) {
    if (!(std::isfinite(value) && value > 0)) {
        violated(std::string("accepted preset gives ") + what + " = " + shortest(value) +
                 "; expected a positive finite number");
    }
}

void check_accepted(const cdvp::BoardPreset& p) {
    const cdvp::SettingValues values = p.applied();
    const cdvp::Settings& s = values.settings();
    check_positive("board.clock_mhz", s.board.clock_mhz);
    check_positive("board clock period (ps)", s.board.period_ps());
    check_positive("host.speed_factor", s.host.speed_factor);
    const std::shared_ptr<const cdvp::BusTiming> bus = values.bus();
    if (!bus) violated("accepted preset has no bus timing");
    check_time("bus PIO read", bus->pio_read_ns());
    check_time("bus PIO write", bus->pio_write_ns());
    check_time("bus interrupt", bus->interrupt_ns());
    for (const uint64_t bytes : {uint64_t{4}, kDmaBytes}) {
        check_time("bus DMA to the board", bus->dma_ns(bytes, cdvp::Direction::kToBoard));
        check_time("bus DMA to the host", bus->dma_ns(bytes, cdvp::Direction::kToHost));
    }
    check_time("host.ns_per_box", s.driver.ns_per_box);
    check_time("host.ns_per_pair", s.driver.ns_per_pair);
    check_time("host.call_ns", s.driver.call_ns);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    preset_fd = memfd_create("preset.json", MFD_CLOEXEC);
    if (preset_fd < 0) violated(std::string("memfd_create: ") + std::strerror(errno));
    preset_path = "/proc/self/fd/" + std::to_string(preset_fd);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    write_preset(data, size);
    cdvp::BoardPreset preset;
    try {
        preset = cdvp::load_board_preset(preset_path);
    } catch (const cdvp::InputError& e) {
        const std::string message = e.what();
        if (message.compare(0, preset_path.size() + 1, preset_path + ":") != 0) {
            violated("error message does not start with the preset's path: " + message);
        }
        if (message.find_first_of("\r\n") != std::string::npos) violated("error message is not one line: " + message);
        return 0;
    }
    check_accepted(preset);
    return 0;
}
