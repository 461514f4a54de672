// The per-user base directories of the XDG Base Directory rules, shared by
// everything cdvp keeps for a user (the host profile, the RTL model cache).
#pragma once

#include <string>

namespace cdvp {

// $VARIABLE when it is an absolute path (the rules say a relative one is to
// be ignored), else $HOME/HOME_FALLBACK when HOME is an absolute path; empty
// when neither is. user_base_directory("XDG_CACHE_HOME", ".cache") is the
// user's cache directory.
std::string user_base_directory(const char* variable, const char* home_fallback);

}  // namespace cdvp
