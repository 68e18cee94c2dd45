// PNG files of Images through libpng: 8-bit RGB, no text or time chunks and a fixed zlib level,
// so the same image always gives the same bytes. Reading accepts any PNG libpng decodes
// (palette, grey, 16-bit, alpha dropped) for golden-image tests. Not a general image library.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "render/image.hpp"

namespace gearsim::render {

// The PNG bytes of an image. Throws InputError for an empty image.
std::vector<std::uint8_t> encode_png(const Image& image);

// Writes encode_png(image) to `path`, whole or not at all (core/output_file.hpp). Throws
// OutputError naming the path and the reason when it cannot be written (missing folder, not a
// folder, no permission, disk full).
void write_png(const Image& image, const std::filesystem::path& path);

// Throws InputError naming the path when it is missing or not a PNG libpng can decode.
Image read_png(const std::filesystem::path& path);

// Writes `bytes` to `path` (binary), or throws OutputError naming the path and the reason.
void write_file(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& path);

}  // namespace gearsim::render
