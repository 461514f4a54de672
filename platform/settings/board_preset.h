// Board presets: data files under platform/boards/, each number with its
// source or stated assumption ({"value": ..., "source": "..."}).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "platform/settings/setting_values.h"

namespace cdvp {

struct BoardPreset {
    std::string name;
    std::string description;
    std::string path;
    // Every setting the preset gives, checked against its range: the layer
    // the preset puts over the defaults (platform/settings/settings.h). What the board,
    // bus, device and host are is read through the settings: applied().
    std::vector<Assignment> values;

    // The defaults with this preset's layer over them (m stays the user's
    // choice, the default until a later layer gives it).
    SettingValues applied() const;
};

// name: a preset in the boards directory (e.g. "adm-xrc-ii"), or a path to a
// .json file. Throws InputError naming the file and the missing or bad field,
// on one line (control characters escaped); an unknown name is refused under
// `label`, how the caller's face names the input ("--board" on the command
// line). Every key must be declared and every number within its setting's
// range (platform/settings/settings.h).
BoardPreset load_board_preset(const std::string& name, const std::string& label = "board");
// The same preset, shared and immutable: the same text read again gives the
// preset parsed before, without a copy (a sweep reads its preset every point).
std::shared_ptr<const BoardPreset> load_shared_board_preset(const std::string& name, const std::string& label = "board");
// The file load_board_preset(name) reads (whether or not it exists).
std::string board_preset_path(const std::string& name);
std::vector<std::string> board_preset_names();
// Where presets live: $CDVP_BOARDS if set, else share/cdvp/boards of the
// prefix the running binary is installed in, else the source tree's platform/boards.
std::string boards_directory();

}  // namespace cdvp
