// Image files: lossless EXR round trip, failed writes leave nothing behind, PNG signature and exposure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "core/error.h"
#include "image/image.h"
#include "test_support.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

using namespace relt;
namespace fs = std::filesystem;

namespace {

// A fresh directory, removed at the end of the test even when an assertion returns early.
struct TempDir {
  std::string path;
  explicit TempDir(const std::string& tag) : path(test::makeTempDir(tag)) {}
  ~TempDir() { fs::remove_all(path); }
};

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Decoded 8-bit RGB of a PNG file.
std::vector<unsigned char> decodePng(const std::string& path, int& w, int& h) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) return {};
  std::vector<unsigned char> out(data, data + size_t(3) * w * h);
  stbi_image_free(data);
  return out;
}

}  // namespace

TEST(Image, MeanIsOverPixelsAndChannels) {
  Image image(2, 1);
  image.rgb = {1, 2, 3, 4, 5, 9};
  EXPECT_DOUBLE_EQ(image.mean(), 4.0);
  EXPECT_EQ(Image().mean(), 0.0);
}

TEST(Image, ExrRoundTripIsBitExact) {
  // Non-square so that a swapped width/height or row stride shows; FLOAT channels with ZIP
  // compression are lossless, so every value must come back bit for bit.
  Image image(5, 3);
  const float special[] = {0.0f, 1e-3f, 1e4f, 1.0f, 0.1f, 3.4e38f, 1e-40f /* subnormal */, -2.5f, 65504.0f};
  for (size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = i < std::size(special) ? special[i] : std::ldexp(1.0f + 0.013f * float(i), int(i % 7) - 3);
  const TempDir tmp("exr");
  const std::string& dir = tmp.path;
  const std::string path = dir + "/out.exr";
  writeExr(path, image);
  const Image back = readExr(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  ASSERT_EQ(back.rgb.size(), image.rgb.size());
  EXPECT_EQ(std::memcmp(back.rgb.data(), image.rgb.data(), image.rgb.size() * sizeof(float)), 0);
  for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_EQ(back.rgb[i], image.rgb[i]) << "index " << i;
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.exr"});  // no temporary left behind
}

// Uncompressed (snapshots, a stop by signal) reads back the same bits as ZIP, and ZIP is smaller.
TEST(Image, AnUncompressedExrReadsBackAsTheCompressedOne) {
  Image image(64, 32);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = 0.25f + 1e-3f * float(i % 64);
  const TempDir tmp("exr-compression");
  const std::string zip = tmp.path + "/zip.exr", none = tmp.path + "/none.exr";
  writeExr(zip, image, {}, {}, ExrCompression::Zip);
  writeExr(none, image, {}, {}, ExrCompression::None);
  EXPECT_EQ(readExr(none).rgb, image.rgb);
  EXPECT_EQ(readExr(zip).rgb, image.rgb);
  EXPECT_GT(std::filesystem::file_size(none), 2 * std::filesystem::file_size(zip));
}

TEST(Image, ExrOverwritesAnExistingFile) {
  const TempDir tmp("exr-over");
  const std::string& dir = tmp.path;
  const std::string path = dir + "/out.exr";
  Image a(1, 1), b(1, 1);
  a.rgb = {1, 2, 3};
  b.rgb = {4, 5, 6};
  writeExr(path, a);
  writeExr(path, b);
  EXPECT_EQ(readExr(path).rgb, b.rgb);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.exr"});
}

TEST(Image, ExrWriteIntoMissingDirectoryThrowsAndCreatesNothing) {
  const TempDir tmp("exr-missing");
  const std::string& dir = tmp.path;
  Image image(2, 2);
  EXPECT_THROW(writeExr(dir + "/no/such/dir/out.exr", image), InputError);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(Image, FailedRenameRemovesTheTemporary) {
  // The target is an existing directory: the temporary is written next to it, then rename fails
  // (EISDIR). Works as root too, unlike a permission-based check. The error names the target.
  const TempDir tmp("exr-rename");
  const std::string& dir = tmp.path;
  const std::string target = dir + "/taken";
  fs::create_directory(target);
  Image image(2, 2);
  try {
    writeExr(target, image);
    ADD_FAILURE() << "writeExr onto a directory did not throw";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), target);
  }
  EXPECT_THROW(writePng(target, image, 0.0f), InputError);
  EXPECT_THROW(writeFileAtomically(target, "text"), InputError);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"taken"});
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_TRUE(fs::is_empty(target));
}

TEST(Image, ReadingAMissingOrNonExrFileThrows) {
  const TempDir tmp("exr-read");
  const std::string& dir = tmp.path;
  EXPECT_THROW(readExr(dir + "/absent.exr"), InputError);
  writeFileAtomically(dir + "/junk.exr", "not an exr file");
  EXPECT_THROW(readExr(dir + "/junk.exr"), InputError);
}

TEST(Image, TemporaryIsAHiddenSiblingOfTheTarget) {
  const fs::path tmp = temporaryPathFor("/some/dir/out.exr");
  EXPECT_EQ(tmp.parent_path(), fs::path("/some/dir"));  // same directory: rename stays atomic
  EXPECT_EQ(tmp.filename().string().rfind(".out.exr.tmp", 0), 0u) << tmp;
}

TEST(Image, PngStartsWithSignatureAndHasTheImageSize) {
  const TempDir tmp("png");
  const std::string& dir = tmp.path;
  Image image(4, 3);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = float(i) / float(image.rgb.size());
  writePng(dir + "/out.png", image, 0.0f);
  const std::string bytes = readBytes(dir + "/out.png");
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  int w = 0, h = 0;
  EXPECT_EQ(decodePng(dir + "/out.png", w, h).size(), 36u);
  EXPECT_EQ(w, 4);
  EXPECT_EQ(h, 3);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.png"});
}

TEST(Image, PngIsSrgbEncodedAndClampsOutOfRangeValues) {
  // Pixel order: linear 0, 1, 0.5 / -1, NaN, 1e4. sRGB(0.5) = 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
  // -> 187.5..., rounded 188; negative and NaN give 0, values above 1 saturate at 255.
  const TempDir tmp("png-srgb");
  const std::string& dir = tmp.path;
  Image image(2, 1);
  image.rgb = {0.0f, 1.0f, 0.5f, -1.0f, std::numeric_limits<float>::quiet_NaN(), 1e4f};
  writePng(dir + "/out.png", image, 0.0f);
  int w = 0, h = 0;
  const std::vector<unsigned char> px = decodePng(dir + "/out.png", w, h);
  const std::vector<unsigned char> expected = {0, 255, 188, 0, 0, 255};
  EXPECT_EQ(px, expected);
}

TEST(Image, ExposureScalesByPowersOfTwo) {
  // Exposure e multiplies linear values by 2^e before encoding: (image, +1) and (2 x image, 0)
  // must give identical files, and 0.25 at exposure +2 reaches white.
  const TempDir tmp("png-exposure");
  const std::string& dir = tmp.path;
  Image image(3, 1), doubled(3, 1);
  image.rgb = {0.01f, 0.1f, 0.25f, 0.3f, 0.05f, 0.002f, 0.125f, 0.2f, 0.4f};
  for (size_t i = 0; i < image.rgb.size(); ++i) doubled.rgb[i] = 2.0f * image.rgb[i];
  writePng(dir + "/a.png", image, 1.0f);
  writePng(dir + "/b.png", doubled, 0.0f);
  writePng(dir + "/c.png", image, 0.0f);
  EXPECT_EQ(readBytes(dir + "/a.png"), readBytes(dir + "/b.png"));
  EXPECT_NE(readBytes(dir + "/a.png"), readBytes(dir + "/c.png"));

  Image quarter(1, 1);
  quarter.rgb = {0.25f, 0.25f, 0.25f};
  writePng(dir + "/d.png", quarter, 2.0f);
  writePng(dir + "/e.png", quarter, -2.0f);  // 1/16 -> sRGB 0.2773 -> 70.7 -> 71
  int w = 0, h = 0;
  EXPECT_EQ(decodePng(dir + "/d.png", w, h), std::vector<unsigned char>(3, 255));
  EXPECT_EQ(decodePng(dir + "/e.png", w, h), std::vector<unsigned char>(3, 71));
}

TEST(Image, NonFinitePixelsAreZeroedAndCountedBeforeWriting) {
  Image image(3, 1);
  image.rgb = {1.0f, 2.0f, 3.0f, std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f,
               0.25f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  EXPECT_EQ(zeroNonFinitePixels(image), 2u);
  EXPECT_EQ(image.rgb, (std::vector<float>{1.0f, 2.0f, 3.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}));
  EXPECT_EQ(zeroNonFinitePixels(image), 0u);  // finite pixels, negative or not, are left alone
}
