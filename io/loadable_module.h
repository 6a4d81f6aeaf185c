// A module: a shared library of twinray's build tree that a process loads on first use, so that
// processes that never use it do not map it or the libraries it links (their resident pages
// count in every process that maps them).
#pragma once

#include <mutex>
#include <string>

namespace tr {

class LoadableModule {
 public:
  // `what` names the module in errors.
  LoadableModule(const char* path, const char* symbol, const char* what)
      : path_(path), symbol_(symbol), what_(what) {}

  // The address of the symbol, the module loaded on the first call (thread-safe). Throws
  // std::runtime_error naming the module and the loader's message when it cannot be loaded.
  void* function();

 private:
  const char* path_;
  const char* symbol_;
  const char* what_;
  std::once_flag once_;
  void* function_ = nullptr;
  std::string failure_;
};

}  // namespace tr
