// `cdvp settings [--json | --markdown]`: every setting of the table
// (platform/settings/settings.h) with its type, unit, default, range or choices,
// dedicated flag, help and the source behind its default.
#pragma once

#include <nlohmann/json.hpp>

namespace cdvp {

int settings_command(int argc, char** argv);
// What --json prints: the table as an array of objects, one a setting.
nlohmann::json settings_json();

}  // namespace cdvp
