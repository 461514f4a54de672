#include "models/common/register_bank.h"

#include <stdexcept>

namespace cdvp {

void RegisterBank::add(std::string name, uint32_t offset, RegisterAccess access,
                                          ReadCallback on_read, WriteCallback on_write) {
    if (offset % 4 != 0) throw std::logic_error("register " + name + " at a misaligned offset");
    if (const Register* taken = find(offset)) {
        throw std::logic_error("register " + name + " declared at the offset of " + taken->name);
    }
    registers_.push_back(Register{std::move(name), offset, access, std::move(on_read), std::move(on_write)});
}

void RegisterBank::add_wide(const std::string& name, uint32_t offset_lo, uint32_t offset_hi, RegisterAccess access,
                            WideReadCallback read, WideWriteCallback write) {
    constexpr uint64_t kLow = 0xffffffffull;
    WriteCallback write_lo, write_hi;
    if (write) {
        write_lo = [read, write](uint32_t v) { return write((read() & ~kLow) | v); };
        write_hi = [read, write](uint32_t v) { return write((read() & kLow) | uint64_t{v} << 32); };
    }
    add(name + "_LO", offset_lo, access, [read] { return static_cast<uint32_t>(read()); }, std::move(write_lo));
    add(name + "_HI", offset_hi, access, [read] { return static_cast<uint32_t>(read() >> 32); }, std::move(write_hi));
}

const RegisterBank::Register* RegisterBank::find(uint32_t offset) const {
    for (const Register& r : registers_) {
        if (r.offset == offset) return &r;
    }
    return nullptr;
}

RegisterBank::Register* RegisterBank::find_mutable(uint32_t offset) {
    return const_cast<Register*>(find(offset));
}

RegisterResult RegisterBank::read(uint32_t offset, uint32_t& value) const {
    const Register* r = find(offset);
    if (r == nullptr) return RegisterResult::kUnmapped;
    if (r->access == RegisterAccess::kWriteOnly) value = 0;
    else value = r->on_read ? r->on_read() : r->value;
    return RegisterResult::kDone;
}

RegisterResult RegisterBank::write(uint32_t offset, uint32_t value) {
    Register* r = find_mutable(offset);
    if (r == nullptr) return RegisterResult::kUnmapped;
    if (r->access == RegisterAccess::kReadOnly) return RegisterResult::kDone;
    if (r->on_write) return r->on_write(value);
    r->value = value;
    return RegisterResult::kDone;
}

}  // namespace cdvp
