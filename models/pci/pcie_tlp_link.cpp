#include "models/pci/pcie_tlp_link.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace cdvp {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
uint64_t data_credits(uint64_t bytes) { return (bytes + kCreditBytes - 1) / kCreditBytes; }
// Bytes from 'address' up to the next multiple of 'boundary' (a whole boundary when aligned).
uint64_t to_boundary(uint64_t address, uint64_t boundary) { return boundary - address % boundary; }

void require(bool ok, const char* what, double got) {
    if (ok) return;
    std::ostringstream s;
    s << what << ", got " << got;
    throw std::invalid_argument(s.str());
}
bool power_of_two(uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

// Flow-control credits one receiver advertises: taken when a TLP is sent,
// back credit_return_ns after it is consumed. Returns arrive in order.
class CreditPool {
public:
    CreditPool(uint64_t headers, uint64_t data) : headers_(headers), data_(data) {}
    // The first time >= at when the need is covered by credits known to come back; NaN if not yet known.
    double available_at(double at, uint64_t headers, uint64_t data) const {
        uint64_t h = headers_, d = data_;
        double t = at;
        for (const auto& [when, rh, rd] : returns_) {
            if (h >= headers && d >= data) break;
            h += rh, d += rd, t = std::max(t, when);
        }
        return h >= headers && d >= data ? t : std::nan("");
    }
    void take(double at, uint64_t headers, uint64_t data) {
        while (!returns_.empty() && std::get<0>(returns_.front()) <= at) {
            headers_ += std::get<1>(returns_.front()), data_ += std::get<2>(returns_.front());
            returns_.pop_front();
        }
        headers_ -= headers, data_ -= data;
    }
    void give_back(double when, uint64_t headers, uint64_t data) { returns_.emplace_back(when, headers, data); }

private:
    uint64_t headers_, data_;
    std::deque<std::tuple<double, uint64_t, uint64_t>> returns_;
};

// One direction of the link: a serial transmitter shared, TLP by TLP in
// round-robin, between the board's TLPs and a background master's.
class Wire {
public:
    Wire(double bytes_per_ns, const PcieConfig& pcie, const PcieLinkConfig& link, double ack_latency_ns,
         const BusLoad* background)
        : rate_(bytes_per_ns), mps_(pcie.max_payload_bytes), link_(link), ack_latency_ns_(ack_latency_ns),
          arrivals_(background != nullptr ? *background : BusLoad{}), rng_(link.error_seed * 0xD1B54A32D192ED03ull + 7) {
        if (background != nullptr) burst_bytes_ = background->burst_bytes;
        next_arrival_ = arrivals_.next();
    }
    // Sends one board TLP whose data is ready at 'ready'; returns when its last byte is received.
    double send(double ready, uint64_t wire_bytes) {
        for (;;) {
            const double bg_at = queue_.empty() ? next_arrival_ : queue_.front();
            const double at = std::max(free_, std::min(ready, bg_at));
            const bool bg_ok = bg_at <= at, board_ok = ready <= at;
            if (board_ok && (!bg_ok || !background_turn_)) {
                background_turn_ = true;
                return transmit(at, wire_bytes);
            }
            while (next_arrival_ <= at) {
                if (queue_.empty()) head_left_ = burst_bytes_;
                queue_.push_back(next_arrival_);
                next_arrival_ = arrivals_.next();
            }
            const uint64_t payload = std::min<uint64_t>(head_left_, mps_);
            transmit(at, payload + link_.tlp_header_bytes + kTlpLinkBytes);
            head_left_ -= payload;
            if (head_left_ == 0) {
                queue_.pop_front();
                head_left_ = burst_bytes_;
            }
            background_turn_ = false;
        }
    }
    double ns_for(uint64_t wire_bytes) const { return wire_bytes / rate_; }
    double free_at() const { return free_; }
    uint64_t replays = 0;

private:
    // A corrupt TLP is NAKed after the ACK latency (or, the NAK lost too, the
    // replay timer fires) and sent again: go-back-N wastes the link meanwhile.
    double transmit(double at, uint64_t wire_bytes) {
        double end = at + ns_for(wire_bytes);
        while (corrupt(wire_bytes)) {
            ++replays;
            const double wait = corrupt(kDllpBytes) ? link_.replay_timer_ns : ack_latency_ns_;
            end += wait + ns_for(wire_bytes);
        }
        free_ = end;
        return end;
    }
    bool corrupt(uint64_t wire_bytes) {
        if (link_.bit_error_rate <= 0) return false;
        const double p = -std::expm1(8.0 * wire_bytes * std::log1p(-link_.bit_error_rate));
        uint64_t z = (rng_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) / 9007199254740992.0 < p;
    }
    double rate_;
    uint64_t mps_;
    PcieLinkConfig link_;
    double ack_latency_ns_;
    ArrivalProcess arrivals_;
    uint64_t rng_;
    uint64_t burst_bytes_ = 0, head_left_ = 0;
    double next_arrival_ = kInf, free_ = 0;
    std::deque<double> queue_;  // arrival times of background bursts not yet sent
    bool background_turn_ = false;
};

}  // namespace

void PcieLinkConfig::validate(const PcieConfig& pcie) const {
    pcie.validate();
    require(power_of_two(pcie.max_payload_bytes) && pcie.max_payload_bytes <= 4096,
            "bus.max_payload_bytes: expected a power of two from 128 to 4096", pcie.max_payload_bytes);
    require(power_of_two(pcie.max_read_request_bytes) && pcie.max_read_request_bytes <= 4096,
            "bus.max_read_request_bytes: expected a power of two from 128 to 4096", pcie.max_read_request_bytes);
    require(tlp_header_bytes == 12 || tlp_header_bytes == 16, "bus.tlp_header_bytes: expected 12 or 16", tlp_header_bytes);
    require(read_completion_boundary_bytes == 64 || read_completion_boundary_bytes == 128,
            "bus.read_completion_boundary_bytes: expected 64 or 128", read_completion_boundary_bytes);
    // A pool must hold the largest TLP (or read) that needs it, or the link would wait forever.
    auto at_least = [](const char* key, uint64_t got, uint64_t least, const std::string& what) {
        if (got >= least) return;
        throw std::invalid_argument(std::string(key) + ": expected at least " + std::to_string(least) + " (" + what +
                                    "), got " + std::to_string(got));
    };
    const uint64_t completions = pcie.max_read_request_bytes / read_completion_boundary_bytes;
    at_least("bus.posted_header_credits", posted_header_credits, 1, "one write");
    at_least("bus.posted_data_credits", posted_data_credits, data_credits(pcie.max_payload_bytes),
             "one max payload of " + std::to_string(pcie.max_payload_bytes) + " bytes");
    at_least("bus.completion_header_credits", completion_header_credits, completions,
             "the completions of one " + std::to_string(pcie.max_read_request_bytes) + "-byte read");
    at_least("bus.completion_data_credits", completion_data_credits, data_credits(pcie.max_read_request_bytes),
             "one " + std::to_string(pcie.max_read_request_bytes) + "-byte read");
    require(credit_return_ns >= 0 && credit_return_ns <= 1e6, "bus.credit_return_ns: expected 0 to 1e6", credit_return_ns);
    require(bit_error_rate >= 0 && bit_error_rate <= 1e-4, "bus.bit_error_rate: expected 0 to 1e-4", bit_error_rate);
    require(replay_timer_ns >= 0 && replay_timer_ns <= 1e6, "bus.replay_timer_ns: expected 0 to 1e6", replay_timer_ns);
}

PcieTlpLink::PcieTlpLink(const PcieConfig& pcie, const PcieLinkConfig& link, const BusLoad& load)
    : pcie_(pcie), link_(link), load_(load) {
    link_.validate(pcie_);
    load_.validate();
}

double PcieTlpLink::bytes_per_ns() const {
    return pcie_.gigatransfers_per_s * pcie_.lanes * pcie_.encoding_efficiency / 8.0;
}

// pcie-bench's estimate: ((max payload + 28) x update factor / width + an
// internal delay of 19, 70 or 115 symbol times by generation) symbol times.
double PcieTlpLink::ack_latency_ns() const {
    const double symbol_ns = 8.0 / (pcie_.gigatransfers_per_s * pcie_.encoding_efficiency);
    const double internal = pcie_.gigatransfers_per_s <= 2.5 ? 19 : pcie_.gigatransfers_per_s <= 5 ? 70 : 115;
    constexpr double kUpdateFactor = 1.4;
    return ((pcie_.max_payload_bytes + 28) * kUpdateFactor / pcie_.lanes + internal) * symbol_ns;
}

PcieOutcome PcieTlpLink::dma(uint64_t bytes, Direction direction, double start_ns, uint64_t address) const {
    PcieOutcome out;
    if (bytes == 0) return out;
    const bool background_up = load_.active() && load_.direction == Direction::kToHost;
    const bool background_down = load_.active() && load_.direction == Direction::kToBoard;
    Wire up(bytes_per_ns(), pcie_, link_, ack_latency_ns(), background_up ? &load_ : nullptr);
    Wire down(bytes_per_ns(), pcie_, link_, ack_latency_ns(), background_down ? &load_ : nullptr);
    const double local = pcie_.local_bus.bytes_per_ns();
    const uint64_t end_address = address + bytes;
    double finish = start_ns;
    if (direction == Direction::kToHost) {
        // Writes: a posted TLP a max payload (aligned to it), sent once its data
        // has come over the local bus and the root complex has posted credits.
        CreditPool credits(link_.posted_header_credits, link_.posted_data_credits);
        for (uint64_t at = address; at < end_address;) {
            const uint64_t payload = std::min(end_address - at, to_boundary(at, pcie_.max_payload_bytes));
            at += payload;
            const double data_ready = start_ns + (at - address) / local;
            const double ready = credits.available_at(data_ready, 1, data_credits(payload));
            out.credit_stall_ns += std::max(0.0, ready - std::max(data_ready, up.free_at()));
            credits.take(ready, 1, data_credits(payload));
            finish = up.send(ready, payload + link_.tlp_header_bytes + kTlpLinkBytes);
            credits.give_back(finish + link_.credit_return_ns, 1, data_credits(payload));
            ++out.requests;
        }
        out.replays = up.replays;
    } else {
        // Reads: a request a max read request; the board issues it only with
        // room in its completion buffer for all of its completions, which the
        // completer splits at RCB-aligned addresses.
        CreditPool credits(link_.completion_header_credits, link_.completion_data_credits);
        // Ready at the completer, payload, DLLP bytes sent before it: the ACK of
        // its request goes down the same wire (one a request, not coalesced).
        std::deque<std::tuple<double, uint64_t, uint64_t>> completions;
        double local_free = start_ns;
        auto deliver_one = [&] {
            const auto [ready, payload, dllp] = completions.front();
            completions.pop_front();
            const double received = down.send(ready, dllp + payload + kCompletionHeaderBytes + kTlpLinkBytes);
            local_free = std::max(local_free, received) + payload / local;  // drained into the FPGA
            credits.give_back(local_free + link_.credit_return_ns, 1, data_credits(payload));
            ++out.completions;
        };
        for (uint64_t at = address; at < end_address;) {
            const uint64_t request = std::min(end_address - at, to_boundary(at, pcie_.max_read_request_bytes));
            std::deque<std::pair<double, uint64_t>> pieces;
            uint64_t headers = 0, data = 0;
            for (uint64_t c = at; c < at + request;) {
                const uint64_t piece = std::min(at + request - c, to_boundary(c, link_.read_completion_boundary_bytes));
                pieces.emplace_back(0.0, piece);
                ++headers, data += data_credits(piece), c += piece;
            }
            double ready = credits.available_at(start_ns, headers, data);
            while (std::isnan(ready)) {  // wait for completions still in flight to free room
                deliver_one();
                ready = credits.available_at(start_ns, headers, data);
            }
            out.credit_stall_ns += std::max(0.0, ready - std::max(start_ns, up.free_at()));
            credits.take(ready, headers, data);
            const double received = up.send(ready, link_.tlp_header_bytes + kTlpLinkBytes);
            for (const auto& piece : pieces) {
                completions.emplace_back(received + pcie_.read_round_trip_ns, piece.second,
                                         &piece == &pieces.front() ? kDllpBytes : 0);
            }
            ++out.requests;
            at += request;
        }
        while (!completions.empty()) deliver_one();
        finish = local_free;
        out.replays = up.replays + down.replays;
    }
    out.ns = finish - start_ns;
    return out;
}

double PcieTlpLink::queueing_ns(uint32_t wire_bytes, Direction direction, double start_ns) const {
    const bool background_here = load_.active() && load_.direction == direction;
    Wire wire(bytes_per_ns(), pcie_, link_, ack_latency_ns(), background_here ? &load_ : nullptr);
    return wire.send(start_ns, wire_bytes) - wire.ns_for(wire_bytes) - start_ns;
}

PcieTlpTiming::PcieTlpTiming(const PcieConfig& pcie, const PcieLinkConfig& link, const BusLoad& load)
    : formula_(pcie), link_(pcie, link, load) {}

std::string PcieTlpTiming::describe() const {
    std::ostringstream s;
    s << formula_.describe() << ", TLP level";
    if (link_.load().active()) s << ", background " << link_.load().bytes_per_s / 1e6 << " MB/s";
    return s.str();
}

template <class F>
double PcieTlpTiming::mean_over_phases(F time_at) const {
    const BusLoad& load = link_.load();
    if (!load.active()) return time_at(0.0);
    double sum = 0;
    for (int k = 0; k < kStartPhases; ++k) {  // as PciTransactionTiming: one phase a gap, a different gap each
        sum += time_at((kWarmupPeriods + k * (1.0 + 1.0 / kStartPhases)) * load.period_ns());
    }
    return sum / kStartPhases;
}

// A PIO read: the formula's round trip plus the waits of its request (down)
// and its completion (up) behind background TLPs.
double PcieTlpTiming::pio_read_ns() const {
    const double round_trip = link_.pcie().read_round_trip_ns;
    return round_trip + mean_over_phases([&](double t) {
               return link_.queueing_ns(12 + kTlpLinkBytes, Direction::kToBoard, t) +
                      link_.queueing_ns(12 + 4 + kTlpLinkBytes, Direction::kToHost, t + round_trip / 2);
           });
}

double PcieTlpTiming::pio_write_ns() const {
    return link_.pcie().posted_write_ns + mean_over_phases([&](double t) {
               return link_.queueing_ns(12 + 4 + kTlpLinkBytes, Direction::kToBoard, t);
           });
}

double PcieTlpTiming::dma_ns(uint64_t bytes, Direction direction) const {
    if (bytes == 0) return 0.0;
    const std::pair<uint64_t, int> key{bytes, direction == Direction::kToHost ? 1 : 0};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    }
    const double ns = mean_over_phases([&](double t) { return link_.dma(bytes, direction, t).ns; });
    std::lock_guard<std::mutex> lock(mutex_);
    memo_[key] = ns;
    return ns;
}

}  // namespace cdvp
