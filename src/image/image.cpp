#include "image/image.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "core/error.h"

namespace relt {

double Image::mean() const {
  double sum = 0.0;
  for (float v : rgb) sum += v;
  return rgb.empty() ? 0.0 : sum / static_cast<double>(rgb.size());
}

uint64_t zeroNonFinitePixels(Image& image) {
  uint64_t changed = 0;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    float* px = &image.rgb[i];
    if (std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2])) continue;
    px[0] = px[1] = px[2] = 0.0f;
    ++changed;
  }
  return changed;
}

void Image::add(const Image& other) {
  for (size_t i = 0; i < rgb.size() && i < other.rgb.size(); ++i) rgb[i] += other.rgb[i];
}

std::string temporaryPathFor(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

void commitTemporary(const std::string& tmp, const std::string& path) {
  // fsync before rename so that a crash leaves either the old or the new file, never a torn one.
  // A full disk can show only here (delayed allocation): then the old file stays.
  const int fd = ::open(tmp.c_str(), O_RDONLY);
  if (fd >= 0) {
    const bool synced = ::fsync(fd) == 0;
    const std::string reason = synced ? "" : std::strerror(errno);
    ::close(fd);
    if (!synced) {
      std::remove(tmp.c_str());
      std::string message = "write failed: ";
      message += reason;
      throw InputError(path, "", message);
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError(path, "", "cannot write: " + reason);
  }
  // The rename itself is durable once the folder is synced too.
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const int dir = ::open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  const std::string_view piece = content;
  writeFileAtomically(path, std::span<const std::string_view>(&piece, 1));
}

void writeFileAtomically(const std::string& path, std::span<const std::string_view> pieces) {
  const std::string tmp = temporaryPathFor(path);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw InputError(path, "", std::string("cannot write: ") + std::strerror(errno));
  bool ok = true;
  for (const std::string_view piece : pieces) ok = ok && std::fwrite(piece.data(), 1, piece.size(), f) == piece.size();
  ok = ok && std::fflush(f) == 0;
  const std::string reason = ok ? "" : std::strerror(errno);
  const bool closed = std::fclose(f) == 0;
  if (!ok || !closed) {
    std::remove(tmp.c_str());
    std::string message = "write failed: ";
    message += ok ? std::strerror(errno) : reason.c_str();
    throw InputError(path, "", message);
  }
  commitTemporary(tmp, path);
}

namespace {
// R, G, B slices of an image under the channel names prefix + "R" etc.
void insertRgb(Imf::FrameBuffer& fb, const Image& image, const std::string& prefix, int minX = 0, int minY = 0) {
  const size_t xs = 3 * sizeof(float), ys = xs * image.width;
  char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgb.data())) - (minX * xs + minY * ys);
  fb.insert(prefix + "R", Imf::Slice(Imf::FLOAT, base, xs, ys));
  fb.insert(prefix + "G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
  fb.insert(prefix + "B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
}
}  // namespace

std::optional<ImageFormat> imageFormatOf(const std::string& path) {
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "exr") return ImageFormat::Exr;
  if (ext == "png") return ImageFormat::Png;
  return std::nullopt;
}

void writeExr(const std::string& path, const Image& image, const std::vector<ImageLayer>& layers,
              const ImageAttributes& attributes, ExrCompression compression) {
  const std::string tmp = temporaryPathFor(path);
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
    for (const auto& [name, value] : attributes) header.insert(name, Imf::StringAttribute(value));
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    for (const ImageLayer& layer : layers)
      for (const char* c : {"R", "G", "B"}) header.channels().insert(layer.name + "." + c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(tmp.c_str(), header);
    Imf::FrameBuffer fb;
    insertRgb(fb, image, "");
    for (const ImageLayer& layer : layers) insertRgb(fb, layer.image, layer.name + ".");
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    std::remove(tmp.c_str());
    throw InputError(path, "", std::string("cannot write EXR: ") + e.what());
  }
  commitTemporary(tmp, path);
}

ImageAttributes readExrAttributes(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    ImageAttributes out;
    for (auto it = file.header().begin(); it != file.header().end(); ++it)
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        out.emplace_back(it.name(), text->value());
    return out;
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot read EXR: ") + e.what());
  }
}

Image readExr(const std::string& path, const std::string& layer) {
  try {
    Imf::InputFile file(path.c_str());
    const std::string prefix = layer.empty() ? "" : layer + ".";
    if (!file.header().channels().findChannel(prefix + "R"))
      throw std::runtime_error("no channel " + prefix + "R");
    const Imath::Box2i dw = file.header().dataWindow();
    Image image(dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1);
    Imf::FrameBuffer fb;
    insertRgb(fb, image, prefix, dw.min.x, dw.min.y);
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot read EXR: ") + e.what());
  }
}

namespace {
unsigned char toSrgb8(float linear) {
  if (!(linear > 0.0f)) return 0;
  const float v = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(std::min(1.0f, v) * 255.0f));
}

void appendToString(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}
}  // namespace

void writePng(const std::string& path, const Image& image, float exposure) {
  const float scale = std::exp2(exposure);
  std::vector<unsigned char> bytes(image.rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = toSrgb8(image.rgb[i] * scale);
  std::string png;
  if (!stbi_write_png_to_func(appendToString, &png, image.width, image.height, 3, bytes.data(), 3 * image.width))
    throw InputError(path, "", "cannot encode PNG");
  writeFileAtomically(path, png);
}

}  // namespace relt
