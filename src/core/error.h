#pragma once
// Errors the user can fix (bad scene, bad option, unwritable output): one type, carrying the file,
// the element and the reason, printed on one line by main with exit code 2.
#include <stdexcept>
#include <string>

namespace relt {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string element, std::string reason)
      : std::runtime_error(format(file, element, reason)),
        file_(std::move(file)), element_(std::move(element)), reason_(std::move(reason)) {}
  const std::string& file() const { return file_; }
  const std::string& element() const { return element_; }
  const std::string& reason() const { return reason_; }

 private:
  static std::string format(const std::string& file, const std::string& element, const std::string& reason) {
    std::string msg = file;
    if (!element.empty()) msg += (msg.empty() ? "" : ": ") + element;
    msg += (msg.empty() ? "" : ": ") + reason;
    return msg;
  }
  std::string file_, element_, reason_;
};

}  // namespace relt
