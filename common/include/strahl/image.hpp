// Images: linear float RGB in memory, written and read in any format OpenImageIO knows, by extension.
// 8-bit formats (PNG, JPEG) are written sRGB-encoded and clamped to [0, 1]; float formats (EXR, HDR, PFM, TIFF)
// keep the linear values as 32-bit floats. Reading reverses that (float data is linear, integer data is
// sRGB-decoded; grey is replicated, alpha dropped), so a PNG round trip is exact to within 8-bit quantisation
// and an EXR round trip is exact.
#pragma once
#include "strahl/math.hpp"
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace strahl {

struct image {
    int width = 0, height = 0;
    std::vector<color> pixels;  // row-major, row 0 at the top

    image() = default;
    image(int w, int h, color fill = color(0.0f)) : width(w), height(h), pixels(std::size_t(w) * h, fill) {}
    color& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const color& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// Cannot write or read an image: unknown extension, unwritable path, missing or corrupt file.
class image_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

void write_image(const std::filesystem::path& file, const image& img);
image read_image(const std::filesystem::path& file);

// An animated image (GIF, where OpenImageIO writes it with several subimages): frames of one size, 8-bit
// sRGB, looping. Returns false, writing nothing, where the format holds no animation; throws image_error
// for empty or unequal frames and for a file that cannot be written.
bool write_animation(const std::filesystem::path& file, const std::vector<image>& frames, int frames_per_second);

struct image_difference {
    double rmse = 0.0;              // root mean square over all channels
    double max_error = 0.0;         // largest absolute channel difference
    std::size_t differing_pixels = 0;  // pixels with any channel differing by more than the tolerance
};
// Throws std::invalid_argument when the sizes differ. Equal values (also equal infinities, and NaN against
// NaN) differ by 0; NaN against anything else differs by +inf, so it always counts as differing.
image_difference compare(const image& a, const image& b, float tolerance = 0.0f);

// A heat map of per-pixel values (counts of box tests, say): a perceptual colour ramp from the smallest to
// the largest value, with a colour legend strip added below the picture, labelled with the range and the
// given label (e.g. "box tests per ray"). values.size() must be width * height, else std::invalid_argument.
// The result is width wide and taller than height: rows [0, height) are the picture, the strip lies below.
// The ramp is viridis over the finite values (all equal: its start); -inf and +inf go to its ends and NaN is
// magenta. The text is drawn with OpenImageIO's render_text and DejaVu Sans (Debian: fonts-dejavu-core), or
// the font file named by $STRAHL_FONT; without a usable font, with a built-in 3x5 pixel font (upper case).
image heat_map(const std::vector<float>& values, int width, int height, const std::string& label);

}  // namespace strahl
