// The translation of the libraries' exceptions to motostab.InputError and motostab.ResultError, and
// the capture of what the libraries write to std::cerr.
#include <algorithm>
#include <iostream>
#include <sstream>

#include "analysis/trim.h"
#include "io/result_error.h"
#include "python/common.h"

namespace motostab::python {

namespace {

// The exception classes of motostab/_errors.py (pure Python, importable before _core). Looked up at
// the first error; kept for the life of the process.
PyObject* getErrorClass(const char* name) {
  return py::object(py::module_::import("motostab._errors").attr(name)).release().ptr();
}

// The libraries name an option of the command line as file "command line", key "--fall-limit"; from
// Python that is the keyword argument fall_limit (file None).
io::InputLocation translateLocation(io::InputLocation w) {
  if (w.file != "command line") return w;
  w.file.clear();
  if (w.key.rfind("--", 0) == 0) {
    w.key = w.key.substr(2);
    std::replace(w.key.begin(), w.key.end(), '-', '_');
  }
  return w;
}

// Raises motostab.InputError with the location of `e` (unknown parts as None).
void raiseInputError(const io::InputError& e) {
  static PyObject* cls = getErrorClass("InputError");
  const io::InputLocation w = translateLocation(e.getLocation());
  auto orNone = [](int v) { return v > 0 ? py::object(py::int_(v)) : py::object(py::none()); };
  auto textOrNone = [](const std::string& s) { return s.empty() ? py::object(py::none()) : py::object(py::str(s)); };
  py::object error = py::reinterpret_borrow<py::object>(cls)(e.what(), py::arg("file") = textOrNone(w.file),
                                                              py::arg("line") = orNone(w.line),
                                                              py::arg("column") = orNone(w.column),
                                                              py::arg("key") = textOrNone(w.key),
                                                              py::arg("reason") = e.getReason());
  PyErr_SetObject(cls, error.ptr());
}

void raiseResultError(const std::exception& e) {
  static PyObject* cls = getErrorClass("ResultError");
  PyErr_SetString(cls, e.what());
}

// Capture of std::cerr: one buffer for every call in flight.
class CaptureBuffer : public std::streambuf {
 public:
  std::string take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(text_, {});
  }

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    std::lock_guard<std::mutex> lock(mutex_);
    text_.push_back(static_cast<char>(c));
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    std::lock_guard<std::mutex> lock(mutex_);
    text_.append(s, static_cast<size_t>(n));
    return n;
  }

 private:
  std::mutex mutex_;
  std::string text_;
};

std::mutex captureMutex;
int captureUsers = 0;
std::streambuf* savedCerr = nullptr;
CaptureBuffer* captureBuffer() {
  static auto* buffer = new CaptureBuffer();  // outlives every call (never destroyed)
  return buffer;
}

}  // namespace

void registerErrors(py::module_& m) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::InputError& e) {
      raiseInputError(e);
    } catch (const io::ResultError& e) {  // a computation without a result (TrimError, NoTurnError, ...)
      raiseResultError(e);
    }
  });
}

CerrCapture::CerrCapture() {
  std::lock_guard<std::mutex> lock(captureMutex);
  if (captureUsers++ == 0) savedCerr = std::cerr.rdbuf(captureBuffer());
}

CerrCapture::~CerrCapture() {
  std::lock_guard<std::mutex> lock(captureMutex);
  if (--captureUsers == 0) std::cerr.rdbuf(savedCerr);
}

std::string CerrCapture::take() { return captureBuffer()->take(); }

void logMessages(const std::string& text) {
  if (text.empty()) return;
  try {
    const py::object logger = py::module_::import("logging").attr("getLogger")("motostab");
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
      if (!line.empty()) logger.attr("info")(line);
  } catch (const py::error_already_set&) {
    PyErr_Clear();  // a broken logging set-up must not hide the call's own result or error
  }
}

io::InputLocation argumentLocation(const std::string& name) { return {"", 0, 0, name}; }

}  // namespace motostab::python
