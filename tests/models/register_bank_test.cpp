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

}  // namespace
}  // namespace cdvp
