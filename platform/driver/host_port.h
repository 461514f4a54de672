// What the board driver needs of the host it runs on, and nothing more:
// programmed I/O on the board's BAR, the host memory the board's DMA engine
// reaches, the current time, waiting, and the interrupt. The platform's host
// CPU implements it, and so may any host (examples/foreign_platform); the
// driver includes nothing of the platform or SystemC.
//
// The contract a port keeps, beyond each function's own sentence:
// - Time in whole femtoseconds. now() and wait() count femtoseconds, and
//   wait(d) moves now() by exactly d: a SystemC host runs its kernel at a
//   1 fs resolution (sc_set_time_resolution(1, SC_FS) before elaborating)
//   and converts with sc_time::from_value() and value(). A port on a coarser
//   clock rounds the driver's waits: the driver refuses it at the first wait
//   that moved its clock by anything else (PortContractError).
// - Each interrupt taken once. Interrupts are told apart by the time their
//   handler ran, and wait_for_interrupt_since() returns at once for each such
//   time once at most: on an untimed bus no time passes between two status
//   reads, and a port that returned the same interrupt again would hold the
//   driver in its loop for ever. The driver refuses a port that returns at
//   once twice at the same time (PortContractError).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace cdvp {

// Simulated time in femtoseconds (the kernel's resolution).
using SimTime = uint64_t;
constexpr double kFsPerNs = 1e6;
// Nanoseconds as a count of femtoseconds, rounded to the nearest.
inline SimTime fs_from_ns(double ns) { return static_cast<SimTime>(ns * kFsPerNs + 0.5); }
inline double ns_from_fs(SimTime fs) { return static_cast<double>(fs) / kFsPerNs; }

// A host port broke the contract above: a defect of the host, not of the
// simulated system or of the input. The message names the rule it broke.
class PortContractError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

class HostPort {
public:
    virtual ~HostPort() = default;

    // One programmed-I/O access of whole words at a BAR address; the time the
    // bus took has passed when it returns. Returns the bus's error text, or
    // an empty string when the access completed.
    virtual std::string read(uint64_t address, void* data, uint32_t length) = 0;
    virtual std::string write(uint64_t address, const void* data, uint32_t length) = 0;

    // Host memory as the CPU sees it (no bus involved): bytes from address on.
    virtual unsigned char* memory(uint64_t address) = 0;
    virtual uint64_t memory_size() const = 0;

    // Femtoseconds (see the contract above).
    virtual SimTime now() const = 0;
    // Lets `duration` of host time pass: now() moves by exactly `duration`.
    virtual void wait(SimTime duration) = 0;
    // Waits until the interrupt handler runs or `timeout` passes, whichever comes first.
    virtual void wait_for_interrupt(SimTime timeout) = 0;
    // The same, but returns at once when the handler already ran at or after
    // `since` and this has not returned at once for that run before (each
    // interrupt taken once: an interrupt that came while the driver was
    // reading a status that did not show its cause yet). A host that does
    // not record when its handler ran waits, and the driver's timeout
    // recovers a missed one.
    virtual void wait_for_interrupt_since(SimTime since, SimTime timeout) {
        (void)since;
        wait_for_interrupt(timeout);
    }
};

}  // namespace cdvp
