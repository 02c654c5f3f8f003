// common/image: writing and reading by extension, compare(), heat maps with their legend.
#include "strahl/image.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

using namespace strahl;

namespace {

// A test pattern: a smooth ramp in every channel, values in (0, 1).
image pattern(int w, int h) {
    image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = color((x + 0.5f) / float(w), (y + 0.5f) / float(h), 0.25f + 0.5f * float((x + y) % 2));
    return img;
}

float luminance(const color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

float srgb_encode(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; }

}  // namespace

TEST_CASE("image: EXR round trip is exact, also for values above one and negative", "[common][image]") {
    const auto dir = test::scratch_dir("image_exr");
    image img = pattern(17, 9);
    img.at(0, 0) = color(12.5f, -0.25f, 1e-7f);
    write_image(dir / "a.exr", img);
    const image back = read_image(dir / "a.exr");
    REQUIRE(back.width == 17);
    REQUIRE(back.height == 9);
    const image_difference d = compare(img, back);
    CHECK(d.max_error == 0.0);
    CHECK(d.differing_pixels == 0);
}

TEST_CASE("image: PNG round trip within 8-bit sRGB quantisation, out-of-range values clamp", "[common][image]") {
    const auto dir = test::scratch_dir("image_png");
    image img = pattern(20, 12);
    img.at(1, 1) = color(3.0f, -1.0f, 0.5f);
    write_image(dir / "a.png", img);
    const image back = read_image(dir / "a.png");
    REQUIRE(back.width == 20);
    REQUIRE(back.height == 12);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float want = std::clamp(img.at(x, y)[c], 0.0f, 1.0f);
                // Half a code step in the encoded domain.
                CHECK(std::fabs(srgb_encode(back.at(x, y)[c]) - srgb_encode(want)) <= 0.5f / 255.0f + 1e-5f);
            }
    CHECK(back.at(1, 1).r == 1.0f);
    CHECK(back.at(1, 1).g == 0.0f);
    // Row 0 stays at the top: the pattern's green grows downwards.
    CHECK(back.at(0, 0).g < back.at(0, 11).g);
}

TEST_CASE("image: write errors are image_error", "[common][image]") {
    const auto dir = test::scratch_dir("image_write_errors");
    const image img = pattern(4, 4);
    CHECK_THROWS_AS(write_image(dir / "a.unknownext", img), image_error);
    CHECK_THROWS_AS(write_image(dir / "no_extension", img), image_error);
    CHECK_THROWS_AS(write_image("/proc/nope/x.png", img), image_error);
    std::ofstream(dir / "file.txt") << "a file, not a folder";
    CHECK_THROWS_AS(write_image(dir / "file.txt" / "x.png", img), image_error);
    CHECK_THROWS_AS(write_image(dir / "empty.png", image()), image_error);
    CHECK_THROWS_WITH(write_image(dir / "a.unknownext", img), Catch::Contains("a.unknownext"));
}

TEST_CASE("image: read errors are image_error", "[common][image]") {
    const auto dir = test::scratch_dir("image_read_errors");
    CHECK_THROWS_AS(read_image(dir / "missing.png"), image_error);
    CHECK_THROWS_WITH(read_image(dir / "missing.png"), Catch::Contains("missing.png"));
    CHECK_THROWS_AS(read_image(dir), image_error);  // a folder
    std::ofstream(dir / "garbage.png", std::ios::binary) << "this is not a PNG file at all";
    CHECK_THROWS_AS(read_image(dir / "garbage.png"), image_error);
    std::ofstream(dir / "garbage.exr", std::ios::binary) << "neither is this an EXR";
    CHECK_THROWS_AS(read_image(dir / "garbage.exr"), image_error);
    // A truncated PNG: a valid header, half the data.
    write_image(dir / "whole.png", pattern(64, 64));
    std::ifstream in(dir / "whole.png", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "truncated.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    CHECK_THROWS_AS(read_image(dir / "truncated.png"), image_error);
}

TEST_CASE("image: compare() on hand-made images", "[common][image]") {
    image a(2, 2, color(0.5f)), b(2, 2, color(0.5f));
    image_difference d = compare(a, b);
    CHECK(d.rmse == 0.0);
    CHECK(d.max_error == 0.0);
    CHECK(d.differing_pixels == 0);

    // One channel of one pixel off by 0.3, another pixel off by 0.1 in all channels.
    b.at(1, 0).g = 0.8f;
    b.at(0, 1) = color(0.6f);
    d = compare(a, b);
    const double e1 = double(0.8f) - 0.5, e2 = double(0.6f) - 0.5;
    CHECK(d.max_error == Approx(e1).epsilon(1e-12));
    CHECK(d.rmse == Approx(std::sqrt((e1 * e1 + 3 * e2 * e2) / 12.0)).epsilon(1e-12));
    CHECK(d.differing_pixels == 2);
    CHECK(compare(a, b, 0.2f).differing_pixels == 1);  // tolerance hides the smaller difference
    CHECK(compare(a, b, 0.5f).differing_pixels == 0);

    // NaN against a number always differs; NaN against NaN and inf against inf do not.
    image n1(1, 1, color(0.0f)), n2(1, 1, color(0.0f));
    n1.at(0, 0).r = std::nanf("");
    CHECK(compare(n1, n2, 1.0f).differing_pixels == 1);
    n2.at(0, 0).r = std::nanf("");
    n1.at(0, 0).g = n2.at(0, 0).g = inf;
    CHECK(compare(n1, n2).differing_pixels == 0);
    CHECK(compare(n1, n2).max_error == 0.0);

    CHECK_THROWS_AS(compare(image(2, 2), image(2, 3)), std::invalid_argument);
}

TEST_CASE("image: heat map has the picture on top and a legend strip below", "[common][image]") {
    const int w = 200, h = 50;
    std::vector<float> values(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) values[std::size_t(y) * w + x] = float(x);  // grows left to right
    const image img = heat_map(values, w, h, "box tests per ray");
    REQUIRE(img.width == w);
    REQUIRE(img.height > h + 20);

    // The picture: brightness grows monotonically along the ramp, ends differ clearly.
    for (int x = 1; x < w; ++x) CHECK(luminance(img.at(x, h / 2)) >= luminance(img.at(x - 1, h / 2)));
    CHECK(luminance(img.at(w - 1, 0)) > 10.0f * luminance(img.at(0, 0)));

    // The legend: a row of the strip holds the ramp (varies left to right); somewhere below it, text
    // (near-white pixels that the ramp never produces).
    bool ramp_row = false, text = false;
    for (int y = h; y < img.height; ++y) {
        const float left = luminance(img.at(w / 8 + 2, y)), right = luminance(img.at(w - w / 8 - 2, y));
        if (left > 0.0f && right > 5.0f * left) ramp_row = true;
        for (int x = 0; x < w; ++x)
            if (img.at(x, y).b > 0.5f && img.at(x, y).r > 0.5f && img.at(x, y).g > 0.5f) text = true;
    }
    CHECK(ramp_row);
    CHECK(text);
    for (const color& c : img.pixels) CHECK(is_finite(c));
}

TEST_CASE("image: heat map with equal values, NaN and inf is defined", "[common][image]") {
    const image flat = heat_map(std::vector<float>(16, 3.0f), 4, 4, "all equal");
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            CHECK(is_finite(flat.at(x, y)));
            CHECK(flat.at(x, y) == flat.at(0, 0));
        }

    std::vector<float> v{0.0f, 1.0f, std::nanf(""), inf, -inf, 0.5f};
    const image img = heat_map(v, 3, 2, "nan");
    for (const color& c : img.pixels) CHECK(is_finite(c));
    CHECK(img.at(0, 1) == img.at(1, 0));  // +inf at the top end, as the maximum
    CHECK(img.at(1, 1) == img.at(0, 0));  // -inf at the bottom end, as the minimum
    CHECK(img.at(2, 0) != img.at(0, 0));  // NaN is off the ramp
    CHECK(img.at(2, 0) != img.at(1, 0));

    const image all_nan = heat_map(std::vector<float>(4, std::nanf("")), 2, 2, "");
    for (const color& c : all_nan.pixels) CHECK(is_finite(c));

    CHECK_THROWS_AS(heat_map(std::vector<float>(5), 2, 2, ""), std::invalid_argument);
    CHECK_THROWS_AS(heat_map({}, 0, 0, ""), std::invalid_argument);
}

TEST_CASE("image: heat map legend falls back to the built-in font without a TrueType font", "[common][image]") {
    ::setenv("STRAHL_FONT", "/nonexistent/font.ttf", 1);
    const image img = heat_map(std::vector<float>(64 * 8, 1.0f), 64, 8, "0123");
    ::unsetenv("STRAHL_FONT");
    int white = 0;
    for (int y = 8; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) white += img.at(x, y) == color(1.0f) ? 1 : 0;
    CHECK(white > 20);
}
