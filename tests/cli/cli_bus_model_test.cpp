// `cdvp run --bus-model transaction`: the detailed bus level end to end, a
// loaded bus slowing the upload, and the refusals of load without it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliBusModel : public Cli {
protected:
    json first_frame(const std::string& args) {
        const Result r = run("run --scene spheres --objects 500 --frames 1 --board adm-xrc-ii -q --report r.json " + args);
        EXPECT_EQ(r.status, 0) << r.err;
        return report_of(dir_ / "r.json")["frames"][0];
    }
};

TEST_F(CliBusModel, ALoadedBusSlowsTheUploadAtTheTransactionLevel) {
    const json formula = first_frame("");
    const json idle = first_frame("--bus-model transaction");
    const json loaded = first_frame("--bus-model transaction -c bus.load_bytes_per_s=40e6");
    // Uploads are DMA reads of host memory: the transaction level is exact there on an idle bus.
    EXPECT_DOUBLE_EQ(idle["upload_ns"].get<double>(), formula["upload_ns"].get<double>());
    EXPECT_GT(loaded["upload_ns"].get<double>(), 1.2 * idle["upload_ns"].get<double>());
    EXPECT_GT(loaded["total_ns"].get<double>(), idle["total_ns"].get<double>());
    EXPECT_EQ(loaded["pairs"], idle["pairs"]) << "the bus changes times, never results";
}

TEST_F(CliBusModel, LoadNeedsTheTransactionLevelAndBadValuesNameTheSetting) {
    expect_refusal(run("run --scene spheres --objects 50 --board adm-xrc-ii -c bus.load_bytes_per_s=1e6"),
                   "cdvp run: -c bus.load_bytes_per_s: expected 0 with bus.model formula (it times an idle bus; give "
                   "--bus-model transaction)\n");
    expect_refusal(run("run --scene spheres --objects 50 --board adm-xrc-ii --bus-model exact"),
                   "cdvp run: --bus-model: expected formula or transaction, got 'exact' (see cdvp run --help)\n");
    expect_refusal(run("run --scene spheres --objects 50 --board pcie-gen3-x8 --bus-model transaction "
                       "-c bus.read_completion_boundary_bytes=96"),
                   "cdvp run: -c bus.read_completion_boundary_bytes: expected 64 or 128, got 96\n");
}

}  // namespace
}  // namespace cdvp::test
