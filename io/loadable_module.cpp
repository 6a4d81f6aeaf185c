#include "io/loadable_module.h"

#include <dlfcn.h>

#include <stdexcept>

namespace tr {

void* LoadableModule::function() {
  std::call_once(once_, [this] {
    void* module = dlopen(path_, RTLD_NOW | RTLD_LOCAL);
    if (module) function_ = dlsym(module, symbol_);
    if (!function_) failure_ = dlerror();
  });
  if (!function_)
    throw std::runtime_error(std::string("cannot load twinray's ") + what_ + " module (" + path_ +
                             "): " + failure_);
  return function_;
}

}  // namespace tr
