#include "runtime/library_log.h"

#include <glog/logging.h>

#include <mutex>
#include <string>

namespace ws {

class LibraryLog::Sink : public google::LogSink {
 public:
  explicit Sink(TextLog& log) : log_(log) {}
  void send(google::LogSeverity severity, const char* /*full_filename*/, const char* base_filename,
            int line, const google::LogMessageTime& /*time*/, const char* message,
            size_t message_len) override {
    const std::string text = std::string("(") + base_filename + ":" + std::to_string(line) + ") " +
                             std::string(message, message_len);
    if (severity >= google::GLOG_ERROR) log_.Error(text);
    else log_.Detail(text);
  }

 private:
  TextLog& log_;
};

LibraryLog::LibraryLog(TextLog& log) : sink_(std::make_unique<Sink>(log)) {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("widestereo");
    for (google::LogSeverity s = google::GLOG_INFO; s < google::NUM_SEVERITIES; ++s)
      google::SetLogDestination(s, "");  // no glog files
    FLAGS_logtostderr = false;
    FLAGS_stderrthreshold = google::GLOG_FATAL;  // the sink says the rest
  });
  google::AddLogSink(sink_.get());
}

LibraryLog::~LibraryLog() { google::RemoveLogSink(sink_.get()); }

}  // namespace ws
