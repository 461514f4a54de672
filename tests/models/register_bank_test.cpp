// Declared registers: decoding, access rights, callbacks, refusals.
#include "models/common/register_bank.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace cdvp {
namespace {

TEST(RegisterBank, DecodesAccessRightsAndCallbacks) {
    RegisterBank bank;
    uint32_t commands = 0, last_command = 0;
    bank.add("ID", 0x0, RegisterAccess::kReadOnly, [] { return 0xABCDu; });
    bank.add("CONTROL", 0x4, RegisterAccess::kWriteOnly, {}, [&](uint32_t v) {
        ++commands;
        last_command = v;
        return RegisterResult::kDone;
    });
    bank.add("SCRATCH", 0x8, RegisterAccess::kReadWrite);
    bank.add("LOCKED", 0xC, RegisterAccess::kReadWrite, {}, [](uint32_t) { return RegisterResult::kRefused; });

    uint32_t v = 7;
    EXPECT_EQ(bank.read(0x0, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0xABCDu);
    EXPECT_EQ(bank.write(0x0, 1), RegisterResult::kDone) << "a read-only register ignores writes";
    EXPECT_EQ((bank.read(0x0, v), v), 0xABCDu);

    EXPECT_EQ(bank.write(0x4, 5), RegisterResult::kDone);
    EXPECT_EQ(commands, 1u);
    EXPECT_EQ(last_command, 5u);
    EXPECT_EQ((bank.read(0x4, v), v), 0u) << "a write-only register reads as 0";

    EXPECT_EQ(bank.write(0x8, 42), RegisterResult::kDone);
    EXPECT_EQ((bank.read(0x8, v), v), 42u) << "no callbacks: the stored value";

    EXPECT_EQ(bank.write(0xC, 1), RegisterResult::kRefused);
    EXPECT_EQ(bank.read(0x10, v), RegisterResult::kUnmapped);
    EXPECT_EQ(bank.write(0x10, 1), RegisterResult::kUnmapped);
    ASSERT_NE(bank.find(0x8), nullptr);
    EXPECT_EQ(bank.find(0x8)->name, "SCRATCH");
}

TEST(RegisterBank, RefusesOverlappingOrMisalignedDeclarations) {
    RegisterBank bank;
    bank.add("A", 0x0, RegisterAccess::kReadWrite);
    EXPECT_THROW(bank.add("B", 0x0, RegisterAccess::kReadWrite), std::logic_error);
    EXPECT_THROW(bank.add("C", 0x2, RegisterAccess::kReadWrite), std::logic_error);
}

// A 64-bit value as NAME_LO and NAME_HI: each half reads its bits, a write
// to one half keeps the other, a refusal leaves the value, and a read-only
// pair ignores writes.
TEST(RegisterBank, DeclaresA64BitValueAsLowAndHighHalves) {
    RegisterBank bank;
    uint64_t address = 0x1122334455667788ull;
    bool locked = false;
    bank.add_wide("ADDRESS", 0x0, 0x4, RegisterAccess::kReadWrite, [&] { return address; }, [&](uint64_t v) {
        if (locked) return RegisterResult::kRefused;
        address = v;
        return RegisterResult::kDone;
    });
    const uint64_t counter = 0xa0000000bull;
    bank.add_wide("COUNTER", 0x8, 0xc, RegisterAccess::kReadOnly, [&] { return counter; });
    ASSERT_NE(bank.find(0x0), nullptr);
    EXPECT_EQ(bank.find(0x0)->name, "ADDRESS_LO");
    EXPECT_EQ(bank.find(0x4)->name, "ADDRESS_HI");
    uint32_t v = 0;
    EXPECT_EQ(bank.read(0x0, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0x55667788u);
    EXPECT_EQ(bank.read(0x4, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0x11223344u);
    EXPECT_EQ(bank.write(0x0, 0xdeadbeefu), RegisterResult::kDone);
    EXPECT_EQ(address, 0x11223344deadbeefull);
    EXPECT_EQ(bank.write(0x4, 0x1u), RegisterResult::kDone);
    EXPECT_EQ(address, 0x00000001deadbeefull);
    locked = true;
    EXPECT_EQ(bank.write(0x4, 0x2u), RegisterResult::kRefused);
    EXPECT_EQ(address, 0x00000001deadbeefull);
    EXPECT_EQ(bank.read(0xc, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0xau);
    EXPECT_EQ(bank.read(0x8, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0xbu);
    EXPECT_EQ(bank.write(0x8, 0x5u), RegisterResult::kDone) << "a read-only register ignores writes";
    EXPECT_EQ(bank.read(0x8, v), RegisterResult::kDone);
    EXPECT_EQ(v, 0xbu);
}

}  // namespace
}  // namespace cdvp
