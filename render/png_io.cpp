#include "render/png_io.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "core/errors.hpp"
#include "render/constants.hpp"
#include "core/output_file.hpp"

namespace gearsim::render {
namespace {

// libpng reports errors by longjmp: the error text is kept here, and only trivially destructible
// objects live between setjmp and the libpng calls that may jump.
struct PngState {
  char message[256] = {};
  std::vector<std::uint8_t>* out = nullptr;  // writing
  const std::vector<std::uint8_t>* in = nullptr;  // reading
  std::size_t read_offset = 0;
  bool io_failed = false;
};

void on_error(png_structp png, png_const_charp message) {
  auto* st = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(st->message, sizeof st->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // libraries never print

void on_write(png_structp png, png_bytep data, png_size_t length) {
  auto* st = static_cast<PngState*>(png_get_io_ptr(png));
  try {
    st->out->insert(st->out->end(), data, data + length);
  } catch (...) {
    st->io_failed = true;  // jump only once the exception is gone
  }
  if (st->io_failed) png_error(png, "out of memory");
}

void on_flush(png_structp) {}

void on_read(png_structp png, png_bytep data, png_size_t length) {
  auto* st = static_cast<PngState*>(png_get_io_ptr(png));
  if (st->read_offset + length > st->in->size()) png_error(png, "file is truncated");
  std::memcpy(data, st->in->data() + st->read_offset, length);
  st->read_offset += length;
}

// Returns false with st.message set on failure.
bool encode(const Image& image, PngState& st, std::vector<png_bytep>& rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &st, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(st.message, sizeof st.message, "libpng: out of memory");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &st, on_write, on_flush);
  png_set_compression_level(png, constants::kPngCompressionLevel);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width_px), static_cast<png_uint_32>(image.height_px), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Decodes into `image` (sized inside, rows pointing into it); false with st.message set on failure.
// Both live in the caller's frame, so nothing here needs destroying after a jump.
bool decode(PngState& st, Image& image, std::vector<png_bytep>& rows) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &st, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    std::snprintf(st.message, sizeof st.message, "libpng: out of memory");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &st, on_read);
  png_read_info(png, info);
  // Everything to 8-bit RGB.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_set_gray_to_rgb(png);
  png_read_update_info(png, info);
  const auto w = static_cast<int>(png_get_image_width(png, info));
  const auto h = static_cast<int>(png_get_image_height(png, info));
  if (png_get_rowbytes(png, info) != static_cast<png_size_t>(w) * 3) png_error(png, "unexpected row layout");
  image.width_px = w;
  image.height_px = h;
  image.rgb.assign(static_cast<std::size_t>(w) * h * 3, 0);
  rows.resize(h);
  for (int y = 0; y < h; ++y) rows[y] = image.rgb.data() + static_cast<std::size_t>(y) * w * 3;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width_px < 1 || image.height_px < 1 || image.rgb.size() != static_cast<std::size_t>(image.width_px) * image.height_px * 3)
    throw InputError("encode_png: empty or inconsistent image (" + std::to_string(image.width_px) + "×" + std::to_string(image.height_px) +
                     ")");
  std::vector<std::uint8_t> out;
  std::vector<png_bytep> rows(image.height_px);
  for (int y = 0; y < image.height_px; ++y)
    rows[y] = const_cast<png_bytep>(image.rgb.data() + static_cast<std::size_t>(y) * image.width_px * 3);
  PngState st;
  st.out = &out;
  if (!encode(image, st, rows)) throw InputError(std::string("encode_png: ") + st.message);
  return out;
}

void write_file(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& path) {
  write_output_file(path, std::string(bytes.begin(), bytes.end()));
}

void write_png(const Image& image, const std::filesystem::path& path) { write_file(encode_png(image), path); }

Image read_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read PNG '" + path.string() + "': " + std::strerror(errno));
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) throw InputError("'" + path.string() + "' is not a PNG file");
  PngState st;
  st.in = &bytes;
  Image image;
  std::vector<png_bytep> rows;
  if (!decode(st, image, rows)) throw InputError("cannot decode PNG '" + path.string() + "': " + st.message);
  return image;
}

}  // namespace gearsim::render
