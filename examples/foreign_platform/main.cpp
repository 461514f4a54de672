// cdvp's collision board as IP in a platform of the example's own: its own
// sc_main, CPU, RAM and interconnect; cdvp's CollisionBoard and PciBridge
// through their sockets and interrupt pins, configured from an installed
// preset through cdvp's settings; cdvp's BoardDriver as the CPU's software.
// Every frame's pairs are checked against a brute-force all-pairs test.
//
//   foreign_platform [PRESET.json [OBJECTS [FRAMES [SETTING=VALUE ...]]]]
//
// SETTING=VALUE as `cdvp run -c` takes it, e.g. driver.upload=delta or
// driver.pair_format=bitmap: the host's RAM is sized from the same call the
// platform uses, BoardDriver::host_memory_bytes with the driver's settings.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <systemc>

#include "host_system.h"
#include "models/board/collision_board.h"
#include "models/common/user_text.h"
#include "models/pci/pci_bridge.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"
#include "platform/driver/board_driver.h"
#include "platform/memory_plan.h"
#include "platform/platform_settings.h"

namespace {

struct Scene {
    uint32_t objects = 400;
    uint32_t frames = 4;
};

// Boxes drifting through a cube, a new position each frame.
std::vector<cdvp::FloatBox> frame_boxes(const Scene& scene, uint32_t frame) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> position(0.0f, 100.0f), size(2.0f, 10.0f), velocity(-1.0f, 1.0f);
    std::vector<cdvp::FloatBox> boxes(scene.objects);
    for (cdvp::FloatBox& box : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = position(random) + velocity(random) * static_cast<float>(frame);
            box.max[axis] = box.min[axis] + size(random);
        }
    }
    return boxes;
}

// Closed intervals on every axis, as the board compares.
cdvp::PairList all_pairs(const std::vector<cdvp::FloatBox>& boxes) {
    cdvp::PairList pairs;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t j = i + 1; j < boxes.size(); ++j) {
            bool overlap = true;
            for (int axis = 0; axis < 3; ++axis) {
                overlap = overlap && boxes[i].min[axis] <= boxes[j].max[axis] && boxes[j].min[axis] <= boxes[i].max[axis];
            }
            if (overlap) pairs.push_back({i, j});
        }
    }
    return pairs;
}

// The preset's settings with the example's own over them, as `cdvp run -c` gives them.
cdvp::SettingValues settings_for(const std::string& preset, const std::vector<std::string>& overrides) {
    cdvp::SettingValues values = cdvp::load_board_preset(preset).applied();
    for (const std::string& text : overrides) values.apply({cdvp::parse_override(text)});
    values.check_board();
    return values;
}

// cdvp refuses a bad configuration with an exception and a one-line
// message, never an abort: a platform can report it and go on.
void show_refusals(const std::string& preset) {
    const auto refused = [](const char* what, const auto& configure) {
        try {
            configure();
            std::cout << "refused " << what << ": NOT REFUSED\n";
        } catch (const cdvp::InputError& e) {
            std::cout << "refused " << what << ": " << e.what() << "\n";
        }
    };
    refused("m too large", [&] { settings_for(preset, {"board.m=40"}); });
    refused("a bad preset value", [&] {
        nlohmann::json bad = nlohmann::json::parse(std::ifstream(preset));
        bad["board"]["clock_mhz"]["value"] = -66;
        const std::string path = "bad-preset.json";
        std::ofstream(path) << bad.dump(2);
        struct Remove {
            std::string path;
            ~Remove() { std::remove(path.c_str()); }
        } remove{path};
        settings_for(path, {});
    });
}

struct Outcome {
    uint64_t pairs = 0;
    uint32_t mismatches = 0;
    double total_ns = 0;
    uint64_t upload_bytes = 0, readback_bytes = 0;
};

// The host software: cdvp's driver on the example's own HostPort.
void run_frames(cdvp::HostPort& port, const Scene& scene, const cdvp::PlatformConfig& config,
                const cdvp::CollisionBoard& board, Outcome& outcome) {
    cdvp::BoardDriver driver(port, board.period().value(), config.driver, config.bus);
    driver.open();
    for (uint32_t frame = 0; frame < scene.frames; ++frame) {
        const std::vector<cdvp::FloatBox> boxes = frame_boxes(scene, frame);
        cdvp::PairList pairs;
        const cdvp::FramePhases phases = driver.run_frame(boxes, pairs);
        const bool equal = cdvp::sorted(pairs) == all_pairs(boxes);
        outcome.mismatches += equal ? 0 : 1;
        outcome.pairs += pairs.size();
        outcome.total_ns += phases.total_ns;
        outcome.upload_bytes += phases.upload_bytes;
        outcome.readback_bytes += phases.readback_bytes;
        std::printf("frame %u: %zu boxes, %zu pairs (%s), %.1f us simulated (upload %.1f, compute %.1f, "
                    "readback %.1f)\n",
                    frame, boxes.size(), pairs.size(), equal ? "= all-pairs test" : "MISMATCH with all-pairs test",
                    phases.total_ns / 1e3, phases.upload_ns / 1e3, phases.compute_ns / 1e3,
                    phases.readback_ns / 1e3);
    }
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);  // HostPort's unit
    const std::string preset = argc > 1 ? argv[1] : std::string(CDVP_BOARDS_DIR) + "/adm-xrc-ii.json";
    Scene scene;
    if (argc > 2) scene.objects = static_cast<uint32_t>(std::stoul(argv[2]));
    if (argc > 3) scene.frames = static_cast<uint32_t>(std::stoul(argv[3]));
    std::vector<std::string> overrides = {"board.m=8", "run.quantum_ns=1000"};
    for (int k = 4; k < argc; ++k) overrides.emplace_back(argv[k]);

    show_refusals(preset);
    cdvp::PlatformConfig config;
    try {
        const cdvp::SettingValues values = settings_for(preset, overrides);
        config = cdvp::platform_config(values);
        config.board = cdvp::planned_board(values.settings(), scene.objects);
    } catch (const cdvp::InputError& e) {
        std::cerr << "foreign_platform: " << e.what() << "\n";
        return 2;
    }
    if (!config.bus) config.bus = std::make_shared<cdvp::IdealBusTiming>();
    tlm::tlm_global_quantum::instance().set(sc_core::sc_time(config.quantum_ns, sc_core::SC_NS));

    cdvp::CollisionBoard board("board", config.board, scene.objects, config.fidelity);
    cdvp::PciBridge bridge("bridge", config.bus);
    example::Interconnect interconnect("interconnect");
    // As the platform sizes it: the pair area for the pair format, the delta records' area when it may upload deltas.
    example::HostRam ram("ram", cdvp::BoardDriver::host_memory_bytes(scene.objects, config.board.collector.buffer_depth,
                                                                      config.driver));
    Outcome outcome;
    example::HostProcessor cpu("cpu", ram, sc_core::sc_time(config.bus->interrupt_ns(), sc_core::SC_NS),
                               [&](cdvp::HostPort& port) { run_frames(port, scene, config, board, outcome); });
    sc_core::sc_signal<bool> fpga_irq("fpga_irq"), inta("inta");

    cpu.socket.bind(interconnect.initiators);
    bridge.pci_master.bind(interconnect.initiators);
    interconnect.targets.bind(ram.socket);
    interconnect.add_route(example::kRamBase, ram.size());
    interconnect.targets.bind(bridge.pci_target);
    interconnect.add_route(example::kBoardBarBase, example::kBoardBarSize, config.bus->pio_read_ns(),
                           config.bus->pio_write_ns());
    bridge.local_bus.bind(board.socket);
    board.irq.bind(fpga_irq);
    bridge.fpga_irq.bind(fpga_irq);
    bridge.inta.bind(inta);
    cpu.irq.bind(inta);

    sc_core::sc_start();
    if (cpu.failure()) {
        try {
            std::rethrow_exception(cpu.failure());
        } catch (const std::exception& e) {
            std::cerr << "foreign_platform: the host software failed: " << e.what() << "\n";
            return 3;
        }
    }
    std::printf("%u frames, %llu pairs, %u mismatches; %.1f us simulated per frame on %s (m=%u)\n", scene.frames,
                static_cast<unsigned long long>(outcome.pairs), outcome.mismatches,
                outcome.total_ns / scene.frames / 1e3, preset.substr(preset.find_last_of('/') + 1).c_str(),
                config.board.m);
    std::printf("bus: %llu bytes of boxes uploaded, %llu bytes of pairs read back\n",
                static_cast<unsigned long long>(outcome.upload_bytes),
                static_cast<unsigned long long>(outcome.readback_bytes));
    return outcome.mismatches == 0 ? 0 : 1;
}
