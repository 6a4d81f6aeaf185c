// Atomic file replacement: write to a uniquely named temporary file in the destination's
// directory, then rename it over the destination (rename(2) is atomic within a file system),
// so readers see the old file or the new one, never a partial one.
#pragma once

#include <stdexcept>
#include <string>

namespace tr {

// Thrown by the file writers of io/; what() is one line, "path: what went wrong".
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A new empty file beside `path`, removed on destruction unless commit() renamed it over
// `path`. Throws FileError.
class TempFile {
 public:
  explicit TempFile(const std::string& path);
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& name() const { return name_; }
  void commit();

 private:
  std::string target_;
  std::string name_;
};

// Writes `text` to `path` atomically. Throws FileError.
void write_text_file(const std::string& path, const std::string& text);

// Creates the folder `path` (and its parents) unless it exists. Throws FileError.
void create_output_folder(const std::string& path);

// A new empty folder under the system's temporary one (mkdtemp), removed with everything in it
// on destruction. Throws FileError.
class TemporaryDirectory {
 public:
  TemporaryDirectory();
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace tr
