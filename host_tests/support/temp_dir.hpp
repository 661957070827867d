#pragma once
// A fresh directory under the system temp dir, removed with its contents.
#include <filesystem>
#include <string>

namespace sinu::test {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to `name` inside the directory and returns its path.
  std::string write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

/// The whole file as bytes (empty if it cannot be read).
std::string read_file(const std::string& path);

}  // namespace sinu::test
