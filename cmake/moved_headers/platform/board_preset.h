// Deprecated: platform/board_preset.h moved to
// platform/settings/board_preset.h. This forwarding header,
// installed at the old path only, keeps programs that include the old path
// building; include the new path instead: the old one will be removed in a
// later release (docs/library.md, The public headers).
#pragma once
#if defined(__GNUC__) && !defined(__clang__) && !defined(CDVP_NO_DEPRECATED_HEADER_NOTE)
#pragma message("platform/board_preset.h is deprecated: include \"platform/settings/board_preset.h\"")
#endif
#include "platform/settings/board_preset.h"
