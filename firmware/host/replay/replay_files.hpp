#pragma once
// The files of a replay folder, each written by a listener of the replay or
// from its result: nav.csv (board/outputs/nav_log.hpp, the same as `sinu
// fly`'s navigation log), innovations.csv (t, source, component, innovation,
// sigma, test_ratio, accepted) and summary.json.
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/board/outputs/nav_log.hpp"
#include "firmware/host/replay/replay_runner.hpp"

namespace sinu::replay {

class NavCsvWriter final : public ReplayListener {
 public:
  NavCsvWriter(std::string path, double period_s) : path_(std::move(path)), period_s_(period_s) {}
  void on_start(const est::Navigator& nav) override;
  void on_nav(const est::NavOutput& out) override;
  /// False (with `error`) if the file could not be created or written.
  bool close(std::string& error);

 private:
  std::string path_;
  double period_s_;
  const est::Navigator* nav_ = nullptr;
  board::NavLog log_;
  bool opened_ = false;
};

class InnovationCsvWriter final : public ReplayListener {
 public:
  explicit InnovationCsvWriter(std::string path) : path_(std::move(path)) {}
  void on_start(const est::Navigator&) override;
  void on_innovation(const est::InnovationRecord& rec) override;
  bool close(std::string& error);

 private:
  std::string path_;
  board::TextSink out_;
  bool opened_ = false;
};

/// summary.json's content.
nlohmann::json summary_json(const ReplayOptions& options, const ReplayResult& result);

/// The whole replay folder: run_replay with the two writers (nav.csv rows at
/// `nav_rate_hz`, 0: every solution) and `extra` listeners, then summary.json.
bool replay_to_folder(const ReplayOptions& options, const std::string& out_dir, double nav_rate_hz,
                      ReplayResult& result, std::string& error, std::span<ReplayListener* const> extra = {},
                      bool warn = true);

}  // namespace sinu::replay
