#include "sw/run/exit_codes.h"

#include <new>
#include <stdexcept>

#include "models/common/user_text.h"

namespace cdvp {

Failure failure_of_current_exception() {
    try {
        throw;
    } catch (const InputError& e) {
        return {kExitBadInput, printable(e.what())};
    } catch (const SystemError& e) {
        return {kExitSystem, printable(e.what())};
    } catch (const std::bad_alloc&) {
        return {kExitInternal, "internal error (a cdvp bug): out of memory past the run's memory budget"};
    } catch (const std::exception& e) {
        return {kExitInternal, "internal error (a cdvp bug): " + printable(e.what())};
    }
}

}  // namespace cdvp
