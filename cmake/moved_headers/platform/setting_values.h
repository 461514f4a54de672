// Deprecated: platform/setting_values.h moved to
// platform/settings/setting_values.h. This forwarding header,
// installed at the old path only, keeps programs that include the old path
// building; include the new path instead: the old one will be removed in a
// later release (docs/library.md, The public headers).
#pragma once
#if defined(__GNUC__) && !defined(__clang__) && !defined(CDVP_NO_DEPRECATED_HEADER_NOTE)
#pragma message("platform/setting_values.h is deprecated: include \"platform/settings/setting_values.h\"")
#endif
#include "platform/settings/setting_values.h"
