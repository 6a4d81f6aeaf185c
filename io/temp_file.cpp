#include "io/temp_file.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

namespace tr {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  std::string line = path + ": " + what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw FileError(line);
}

}  // namespace

TempFile::TempFile(const std::string& path) : target_(path) {
  fs::path dest(path);
  fs::path dir = dest.parent_path().empty() ? fs::path(".") : dest.parent_path();
  std::string pattern = (dir / ("." + dest.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  int fd = mkstemp(name.data());
  if (fd < 0) fail(path, "cannot create a temporary file in " + dir.string());
  // mkstemp creates the file 0600; give it the permissions a plain create would (0666 & ~umask).
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  name_ = name.data();
}

TempFile::~TempFile() {
  if (!name_.empty()) unlink(name_.c_str());
}

void TempFile::commit() {
  std::error_code ec;
  fs::rename(name_, target_, ec);
  if (ec) fail(target_, "cannot rename the written file into place: " + ec.message());
  name_.clear();
}

void write_text_file(const std::string& path, const std::string& text) {
  TempFile tmp(path);
  {
    std::ofstream out(tmp.name(), std::ios::binary);
    out << text;
    out.flush();
    if (!out) fail(path, "write failed");
  }
  tmp.commit();
}

void create_output_folder(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) throw FileError(path + ": cannot create the output folder: " + ec.message());
}

TemporaryDirectory::TemporaryDirectory() {
  std::string pattern = (std::filesystem::temp_directory_path() / "twinray-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw FileError(pattern + ": cannot create a temporary folder");
  path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace tr
