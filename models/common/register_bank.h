// A peripheral's registers as declared objects, in the spirit of MachineWare
// VCML's reg<T>: each register has a name, an offset, access rights and
// optional read and write callbacks, and the bank decodes offsets. A model
// declares its registers once, in its constructor, instead of hand-writing
// read and write switch statements that must be kept in step.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cdvp {

enum class RegisterAccess : uint8_t { kReadOnly, kWriteOnly, kReadWrite };

// What became of an access: done, no register at that offset, or refused by
// the register's write callback (the model then reports why, e.g. a status bit).
enum class RegisterResult : uint8_t { kDone, kUnmapped, kRefused };

class RegisterBank {
public:
    // Returns the value the host reads.
    using ReadCallback = std::function<uint32_t()>;
    // Takes the value the host wrote; may refuse it.
    using WriteCallback = std::function<RegisterResult(uint32_t)>;

    struct Register {
        std::string name;  // as in the register map of docs/model.md
        uint32_t offset;
        RegisterAccess access;
        ReadCallback on_read;    // none: the stored value
        WriteCallback on_write;  // none: store the value
        uint32_t value = 0;      // storage for registers without callbacks
    };

    // Declares a register; throws std::logic_error if its offset is taken or
    // not word-aligned (a defect in the model, found at construction).
    void add(std::string name, uint32_t offset, RegisterAccess access, ReadCallback on_read = {},
                  WriteCallback on_write = {});

    // A 64-bit value as two registers, NAME_LO (bits 31..0) and NAME_HI
    // (bits 63..32), each read from `read`; a write to either half hands the
    // whole value, that half replaced, to `write` (none: read-only).
    using WideReadCallback = std::function<uint64_t()>;
    using WideWriteCallback = std::function<RegisterResult(uint64_t)>;
    void add_wide(const std::string& name, uint32_t offset_lo, uint32_t offset_hi, RegisterAccess access,
                  WideReadCallback read, WideWriteCallback write = {});

    // A write-only register reads as 0; a write to a read-only register is
    // ignored, as on the hardware (both kDone).
    RegisterResult read(uint32_t offset, uint32_t& value) const;
    RegisterResult write(uint32_t offset, uint32_t value);

    const Register* find(uint32_t offset) const;
    const std::vector<Register>& registers() const { return registers_; }

private:
    Register* find_mutable(uint32_t offset);
    std::vector<Register> registers_;  // in declaration order; banks are small
};

}  // namespace cdvp
