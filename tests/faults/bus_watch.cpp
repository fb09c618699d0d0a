#include "bus_watch.h"

#include <chrono>
#include <stdexcept>

#include "lcm_io/channels.h"

namespace ws::test {

BusWatch::BusWatch(const std::string& url, std::string process)
    : lcm_(url), process_(std::move(process)) {
  if (!lcm_.good()) throw std::runtime_error("cannot open LCM " + url);
  lcm_.subscribeFunction(
      ws::channel::kProcessStatus,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string&, BusWatch* self) {
        widestereo::process_status_t status;
        if (status.decode(rbuf->data, 0, int(rbuf->data_size)) > 0 && status.name == self->process_)
          self->status_ = status;
      },
      this);
}

void BusWatch::Collect(const std::string& channel) {
  payloads_[channel];
  lcm_.subscribeFunction(
      channel,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string& ch, BusWatch* self) {
        const auto* bytes = static_cast<const uint8_t*>(rbuf->data);
        self->payloads_[ch].emplace_back(bytes, bytes + rbuf->data_size);
      },
      this);
}

void BusWatch::Publish(const std::string& channel, const std::vector<uint8_t>& payload) {
  lcm_.publish(channel, payload.data(), unsigned(payload.size()));
}

bool BusWatch::ListenUntil(double seconds, const std::function<bool()>& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        end - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    lcm_.handleTimeout(int(std::min<long>(left.count(), 10)));
  }
  return true;
}

widestereo::channel_counters_t BusWatch::Counters(const std::string& channel) const {
  if (status_)
    for (const auto& c : status_->channels)
      if (c.channel == channel) return c;
  return {};
}

bool StartMatching(BusWatch& bus, const widestereo::stereo_calibration_t& calibration, double seconds) {
  if (!bus.ListenUntil(seconds, [&] { return bus.status().has_value(); })) return false;
  bus.Publish(ws::channel::kStereoCalibration, calibration);
  return bus.ListenUntil(seconds, [&] { return bus.status() && bus.status()->state == "matching"; });
}

}  // namespace ws::test
