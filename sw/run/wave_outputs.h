// The waveform outputs of `cdvp run --vcd FILE`: the dump (a VCD, or with
// --vcd-format fst an FST made from a scratch VCD by vcd2fst), the GTKWave
// save file beside it and the translate filter files the save file points at
// (state names). Each is one output of the run's transaction.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/common/wave_list.h"
#include "platform/settings/setting_names.h"
#include "sw/output/output_set.h"

namespace cdvp {

class VirtualBoard;

enum class DumpFormat { kVcd, kFst };
// "vcd" or "fst"; throws InputError naming the format's input (names) otherwise,
// and for fst when vcd2fst (Debian's gtkwave package) is not on PATH.
DumpFormat parse_dump_format(const std::string& text, const SettingNames& names);

class WaveOutputs {
public:
    // Declares the dump and, for a dump to a file, the save file ("w.vcd" or
    // "w.fst" -> "w.gtkw") and the filter files of the state tables the dump
    // holds ("w.controller-states.txt"; VirtualBoard::state_tables).
    // label: how the face names the waveforms' input ("--vcd").
    void declare(OutputSet& files, const std::string& path, DumpFormat format, const std::string& label,
                 const std::vector<const StateNames*>& tables);
    // After files.open(): binds the declared outputs; for an FST, makes the
    // scratch VCD beside it.
    void bind(OutputSet& files);
    // The base name SystemC writes the VCD to (it appends ".vcd"); empty
    // when no waveforms were asked for.
    std::string trace_base() const;
    // After the platform closed its trace: the FST from the VCD, the save
    // file and the filters. The error's one line if vcd2fst failed.
    std::optional<std::string> finish(const VirtualBoard& platform);

private:
    std::string path_;
    DumpFormat format_ = DumpFormat::kVcd;
    std::optional<std::size_t> dump_index_, save_index_;
    std::vector<const StateNames*> tables_;
    std::map<std::string, std::size_t> filter_indices_;  // by state table
    OutputFile* dump_ = nullptr;
    std::optional<OutputFile> scratch_vcd_;  // fst only: never published
    OutputSet* files_ = nullptr;
};

}  // namespace cdvp
