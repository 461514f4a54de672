// `cdvp settings [--json | --markdown]`: every setting of the table
// (platform/settings.h) with its type, unit, default, range or choices,
// dedicated flag, help and the source behind its default.
#pragma once

namespace cdvp {

int settings_command(int argc, char** argv);

}  // namespace cdvp
