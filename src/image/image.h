#pragma once
// Float RGB images and their files: OpenEXR (float channels) and PNG previews (sRGB, exposure).
// Every write goes to a temporary file in the same directory and is renamed into place, so a
// reader never sees a partial image.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace relt {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major from the top, 3 floats per pixel

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(size_t(3) * w * h, 0.0f) {}
  double mean() const;  // mean over pixels and channels
  void add(const Image& other);  // pixel by pixel; same size
};

// The last check before an image is written: every pixel with a channel that is NaN or infinite
// becomes black. Returns how many pixels it changed (the integrators must not make any).
uint64_t zeroNonFinitePixels(Image& image);

// A named extra layer of an EXR (channels NAME.R, NAME.G, NAME.B), e.g. one per replica level.
struct ImageLayer {
  std::string name;
  Image image;
};

// What a file name's extension (any case) asks for: .exr or .png; anything else is none.
enum class ImageFormat { Exr, Png };
std::optional<ImageFormat> imageFormatOf(const std::string& path);

// Text attributes of an EXR header (name, value), e.g. what rendered it.
using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

// How an EXR is written: ZIP-compressed (about 30 % smaller on a render, but 0.7 s at 1024x768),
// or uncompressed (0.02 s there) for images written against a clock (snapshots, a stop by signal).
enum class ExrCompression { Zip, None };

// Throws InputError (file, "", reason) if the file cannot be written or read.
void writeExr(const std::string& path, const Image& image, const std::vector<ImageLayer>& layers = {},
              const ImageAttributes& attributes = {}, ExrCompression compression = ExrCompression::Zip);
// The header's text attributes, in the header's order.
ImageAttributes readExrAttributes(const std::string& path);
// The main RGB channels, or those of `layer`.
Image readExr(const std::string& path, const std::string& layer = "");
void writePng(const std::string& path, const Image& image, float exposure);

// Writes `content` to `path` atomically (temporary file, fsync, rename).
void writeFileAtomically(const std::string& path, const std::string& content);
// The same for content in pieces, written one after the other (no copy into one buffer).
void writeFileAtomically(const std::string& path, std::span<const std::string_view> pieces);
// A temporary name next to `path` for atomic writes.
std::string temporaryPathFor(const std::string& path);
void commitTemporary(const std::string& tmp, const std::string& path);

}  // namespace relt
