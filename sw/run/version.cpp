#include "sw/run/version.h"

namespace cdvp {

const char* const kCdvpVersion = CDVP_VERSION;

}  // namespace cdvp
