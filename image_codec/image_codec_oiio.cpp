// The OpenImageIO side of fspm/image_codec.hpp, built as a module that fspm loads when it first
// reads or writes an image. It links only OpenImageIO and the standard library.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fspm/image_codec.hpp"

namespace {

// Decoders' own complaints: libpng's default handlers print "libpng error: ..." on stderr before
// OpenImageIO reports the failure, which would break the command line's one line of error. While
// a decoder runs, stderr goes to an anonymous file; its text is folded into the error of a failed
// read, and passed on to stderr after a successful one (a decoder's warnings stay visible).
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = ::memfd_create("fspm_decoder_stderr", MFD_CLOEXEC);
    saved_ = file_ >= 0 ? ::dup(2) : -1;
    if (saved_ < 0 || ::dup2(file_, 2) < 0) close_all();
  }
  ~StderrCapture() { text(); }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // Restores stderr and returns what was written to it meanwhile, on one line.
  std::string text() {
    if (saved_ < 0) return {};
    std::fflush(stderr);
    ::dup2(saved_, 2);
    std::string out;
    char buffer[4096];
    const ssize_t n = ::pread(file_, buffer, sizeof buffer, 0);
    for (ssize_t i = 0; i < n; ++i) out += buffer[i] == '\n' ? ' ' : buffer[i];
    close_all();
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
  }

 private:
  void close_all() {
    if (saved_ >= 0) ::close(saved_);
    if (file_ >= 0) ::close(file_);
    saved_ = file_ = -1;
  }
  int file_ = -1;
  int saved_ = -1;
};

// A failed read's error on one line ("; " between OpenImageIO's lines), with the decoder's own
// words when it printed any that the error does not already hold.
std::string with_decoder_text(const std::string& error, const std::string& decoder) {
  std::string out;
  for (char c : error) {
    if (c != '\n') {
      out += c;
    } else if (!out.empty() && !out.ends_with("; ")) {
      out += "; ";
    }
  }
  while (out.ends_with("; ")) out.resize(out.size() - 2);
  if (decoder.empty() || out.find(decoder) != std::string::npos) return out;
  return out.empty() ? decoder : out + " (" + decoder + ")";
}

// A successful read's decoder output, passed on to stderr.
void pass_on(const std::string& decoder) {
  if (!decoder.empty()) std::fprintf(stderr, "%s\n", decoder.c_str());
}

using fspm::ImageInfo;
using fspm::PixelType;

OIIO::TypeDesc type_of(PixelType type) {
  return type == PixelType::kFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
}

bool writer_format(const std::string& path, std::string& format) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return false;
  format = out->format_name();
  return true;
}

bool read_info(const std::string& path, ImageInfo& info, std::string& error) {
  StderrCapture capture;
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = with_decoder_text(OIIO::geterror(), capture.text());
    return false;
  }
  pass_on(capture.text());
  const OIIO::ImageSpec& spec = in->spec();
  info.width = spec.width;
  info.height = spec.height;
  info.channels = spec.nchannels;
  info.bytes_per_value = static_cast<int>(spec.format.size());
  return true;
}

bool read_pixels(const std::string& path, int channels, PixelType type, void* out,
                 std::string& error) {
  StderrCapture capture;
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = with_decoder_text(OIIO::geterror(), capture.text());
    return false;
  }
  if (!in->read_image(0, 0, 0, channels, type_of(type), out)) {
    error = with_decoder_text(in->geterror(), capture.text());
    return false;
  }
  pass_on(capture.text());
  return true;
}

bool encode(const std::string& path, const ImageInfo& shape, PixelType type, const void* data,
            std::vector<unsigned char>& bytes, std::string& error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "unknown image format";
    return false;
  }
  if (!out->supports("ioproxy")) {
    error = std::string("format '") + out->format_name() + "' cannot be encoded in memory";
    return false;
  }
  OIIO::ImageSpec spec(shape.width, shape.height, shape.channels, type_of(type));
  OIIO::Filesystem::IOVecOutput memory;  // encode in memory: the caller writes atomically
  if (!out->set_ioproxy(&memory) || !out->open(path, spec) ||
      !out->write_image(type_of(type), data) || !out->close()) {
    error = out->geterror();
    return false;
  }
  bytes = memory.buffer();
  return true;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const fspm::ImageCodecApi fspm_image_codec_api{
    fspm::kImageCodecApiVersion, writer_format, read_info, read_pixels, encode};
