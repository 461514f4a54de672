// GTKWave's save file (.gtkw) for the platform's waveforms, and the translate
// filter files it points at so that state vectors read as names.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "models/common/wave_list.h"

namespace cdvp {

// Where the viewer opens: a span of simulated time in femtoseconds (the
// unit of the platform's VCD and of the RTL's), with named markers at
// moments inside it.
struct WaveView {
    uint64_t begin_fs = 0;
    uint64_t end_fs = 0;  // begin_fs == end_fs: nothing to frame, the viewer's default view
    struct Marker {
        std::string name;
        uint64_t at_fs;
    };
    std::vector<Marker> markers;  // the first is also the primary marker
};

struct SaveFile {
    std::string dump_path;  // the VCD or FST, absolute
    std::vector<TracedSignal> signals;
    WaveView view;
    // A translate filter file for each named-state table, by table name.
    std::map<std::string, std::string> filter_paths;
    // The dump's root scope before each signal's name: SystemC's VCD nests
    // everything in "SystemC"; empty where the names are full (the RTL's VCD).
    std::string top_scope = "SystemC";
};

// The window the save file asks for, in pixels, and the width of its
// signal-name pane: they decide the zoom that fits the view.
constexpr int kSaveFileWindowWidth = 1400;
constexpr int kSaveFileWindowHeight = 850;
constexpr int kSaveFileSignalsWidth = 300;

// A signal's full name as GTKWave resolves it in the VCD (and in an FST
// made from it): "SystemC.platform.board.control.state[1:0]".
std::string viewer_name(const TracedSignal& signal, const std::string& top_scope = "SystemC");
// The zoom (GTKWave's "*" line) at which a span of fs fills the wave pane
// of the save file's window, or a little less than it.
double viewer_zoom(uint64_t span_fs);

void write_save_file(std::ostream& out, const SaveFile& save);
// A translate filter file: one "value name" line per named state.
void write_translate_filter(std::ostream& out, const StateNames& states);

}  // namespace cdvp
