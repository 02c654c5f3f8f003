// Images through OpenImageIO: writing and reading by extension, comparing, and heat maps with a legend.
//
// Encoding: formats that store floats (OpenEXR, Radiance HDR, PFM, TIFF) are written as 32-bit float linear
// RGB; every other format is written as 8-bit, sRGB-encoded and clamped to [0, 1]. Reading looks at what the
// file holds: float or half data is taken as linear, integer data as sRGB-encoded and decoded.
#include "strahl/image.hpp"
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>

namespace strahl {
namespace {

// ---- sRGB transfer function (IEC 61966-2-1) ----------------------------------------------------------------
float srgb_encode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also NaN
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

bool is_float_format(std::string_view format_name) {
    return format_name == "openexr" || format_name == "hdr" || format_name == "pfm" || format_name == "tiff";
}

std::string quoted(const std::filesystem::path& file) { return "'" + file.string() + "'"; }

}  // namespace

// ---- writing -------------------------------------------------------------------------------------------------
void write_image(const std::filesystem::path& file, const image& img) {
    if (img.width <= 0 || img.height <= 0)
        throw image_error("write_image " + quoted(file) + ": the image is empty (" + std::to_string(img.width) +
                          " x " + std::to_string(img.height) + ")");
    if (img.pixels.size() != std::size_t(img.width) * std::size_t(img.height))
        throw image_error("write_image " + quoted(file) + ": pixel count does not match width x height");

    // Choose the writer by extension.
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) {
        OIIO::geterror();  // clear the global error message
        throw image_error("write_image " + quoted(file) + ": no image format for the extension '" +
                          file.extension().string() + "'");
    }
    const bool floats = is_float_format(out->format_name());

    // Convert: linear floats as they are, or sRGB-encoded 8-bit.
    const std::size_t n = img.pixels.size();
    OIIO::ImageSpec spec(img.width, img.height, 3, floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", floats ? "Linear" : "sRGB");
    std::vector<float> linear;
    std::vector<unsigned char> encoded;
    if (floats) {
        linear.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) linear[3 * i + c] = img.pixels[i][c];
    } else {
        encoded.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                encoded[3 * i + c] = static_cast<unsigned char>(std::lround(255.0f * srgb_encode(img.pixels[i][c])));
    }

    // Write: open (fails for an unwritable path), write, close (flushes; may fail too).
    if (!out->open(file.string(), spec))
        throw image_error("write_image " + quoted(file) + ": cannot open for writing: " + out->geterror());
    const bool wrote = floats ? out->write_image(OIIO::TypeDesc::FLOAT, linear.data())
                              : out->write_image(OIIO::TypeDesc::UINT8, encoded.data());
    const bool closed = out->close();
    if (!wrote || !closed) throw image_error("write_image " + quoted(file) + ": writing failed: " + out->geterror());
}

bool write_animation(const std::filesystem::path& file, const std::vector<image>& frames, int frames_per_second) {
    if (frames.empty()) throw image_error("write_animation " + quoted(file) + ": no frames");
    for (const image& f : frames)
        if (f.width != frames[0].width || f.height != frames[0].height || f.width <= 0 || f.height <= 0 ||
            f.pixels.size() != std::size_t(f.width) * std::size_t(f.height))
            throw image_error("write_animation " + quoted(file) + ": frames of different or empty sizes");
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out || !out->supports("multiimage") || !out->supports("appendsubimage")) {
        OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(frames[0].width, frames[0].height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("FramesPerSecond", OIIO::TypeRational, std::array<int, 2>{frames_per_second, 1}.data());
    spec.attribute("oiio:LoopCount", 0);  // loop for ever
    std::vector<unsigned char> encoded(3 * frames[0].pixels.size());
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const bool opened = k == 0 ? out->open(file.string(), spec) : out->open(file.string(), spec, OIIO::ImageOutput::AppendSubimage);
        if (!opened) throw image_error("write_animation " + quoted(file) + ": cannot open for writing: " + out->geterror());
        for (std::size_t i = 0; i < frames[k].pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                encoded[3 * i + c] = static_cast<unsigned char>(std::lround(255.0f * srgb_encode(frames[k].pixels[i][c])));
        if (!out->write_image(OIIO::TypeDesc::UINT8, encoded.data()))
            throw image_error("write_animation " + quoted(file) + ": writing failed: " + out->geterror());
    }
    if (!out->close()) throw image_error("write_animation " + quoted(file) + ": writing failed: " + out->geterror());
    return true;
}

// ---- reading -------------------------------------------------------------------------------------------------
image read_image(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw image_error("read_image " + quoted(file) + ": no such file");

    // Open: fails for an unknown or corrupt header.
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        const std::string why = OIIO::geterror();
        throw image_error("read_image " + quoted(file) + ": cannot read: " + (why.empty() ? "unknown format" : why));
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int w = spec.width, h = spec.height, channels = spec.nchannels;
    if (w <= 0 || h <= 0 || channels <= 0)
        throw image_error("read_image " + quoted(file) + ": the file holds an empty image");
    const bool floats = spec.format.is_floating_point();

    // Read all channels as floats (OIIO scales integers to [0, 1]).
    std::vector<float> data(std::size_t(w) * h * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
        const std::string why = in->geterror();
        in->close();
        throw image_error("read_image " + quoted(file) + ": corrupt or truncated: " + why);
    }
    in->close();

    // Convert: grey (1 or 2 channels) replicates, alpha is dropped, integer data is sRGB-decoded.
    image img(w, h);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) {
        const float* p = &data[i * channels];
        color c = channels >= 3 ? color(p[0], p[1], p[2]) : color(p[0]);
        if (!floats) c = color(srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b));
        img.pixels[i] = c;
    }
    return img;
}

// ---- comparing -----------------------------------------------------------------------------------------------
// Channel difference: equal values (also equal infinities and two NaNs) differ by 0; a NaN against anything
// else differs by +inf, so it always counts.
image_difference compare(const image& a, const image& b, float tolerance) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("compare: image sizes differ (" + std::to_string(a.width) + " x " +
                                    std::to_string(a.height) + " against " + std::to_string(b.width) + " x " +
                                    std::to_string(b.height) + ")");
    image_difference d;
    double sum_sq = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const float x = a.pixels[i][c], y = b.pixels[i][c];
            double e = 0.0;
            if (std::isnan(x) || std::isnan(y)) e = (std::isnan(x) && std::isnan(y)) ? 0.0 : double(inf);
            else if (x != y) e = std::fabs(double(x) - double(y));  // inf - inf cannot occur here
            sum_sq += e * e;
            d.max_error = std::max(d.max_error, e);
            differs = differs || e > double(tolerance);
        }
        d.differing_pixels += differs ? 1 : 0;
    }
    if (!a.pixels.empty()) d.rmse = std::sqrt(sum_sq / (3.0 * double(a.pixels.size())));
    return d;
}

// ---- heat maps -----------------------------------------------------------------------------------------------
namespace {

// Viridis (matplotlib, van der Walt and Smith 2015), sRGB-encoded, at 17 evenly spaced points.
constexpr std::array<std::array<float, 3>, 17> viridis{{
    {0.267004f, 0.004874f, 0.329415f}, {0.282327f, 0.094955f, 0.417331f}, {0.278826f, 0.175490f, 0.483397f},
    {0.258965f, 0.251537f, 0.524736f}, {0.229739f, 0.322361f, 0.545706f}, {0.199430f, 0.387607f, 0.554642f},
    {0.172719f, 0.448791f, 0.557885f}, {0.149039f, 0.508051f, 0.557250f}, {0.127568f, 0.566949f, 0.550556f},
    {0.120638f, 0.625828f, 0.533488f}, {0.157851f, 0.683765f, 0.501686f}, {0.246070f, 0.738910f, 0.452024f},
    {0.369214f, 0.788888f, 0.382914f}, {0.515992f, 0.831158f, 0.294279f}, {0.678489f, 0.863742f, 0.189503f},
    {0.845561f, 0.887322f, 0.099702f}, {0.993248f, 0.906157f, 0.143936f},
}};

// The ramp at t in [0, 1], interpolated in sRGB and returned linear (images hold linear RGB).
color ramp(float t) {
    t = std::clamp(t, 0.0f, 1.0f) * float(viridis.size() - 1);
    const int k = std::min(int(t), int(viridis.size()) - 2);
    const float f = t - float(k);
    color c;
    for (int i = 0; i < 3; ++i) c[i] = srgb_decode((1.0f - f) * viridis[k][i] + f * viridis[k + 1][i]);
    return c;
}

const color nan_colour{1.0f, 0.0f, 1.0f};  // magenta: not on the ramp

// Fallback text: a 3 x 5 pixel font, one octal digit per row (4 = left pixel, 1 = right pixel).
struct glyph {
    char c;
    const char* rows;
};
constexpr glyph tiny_font[] = {
    {'0', "75557"}, {'1', "26227"}, {'2', "71747"}, {'3', "71317"}, {'4', "55711"}, {'5', "74717"},
    {'6', "74757"}, {'7', "71111"}, {'8', "75757"}, {'9', "75717"}, {'A', "25755"}, {'B', "65656"},
    {'C', "34443"}, {'D', "65556"}, {'E', "74647"}, {'F', "74644"}, {'G', "34553"}, {'H', "55755"},
    {'I', "72227"}, {'J', "11153"}, {'K', "55655"}, {'L', "44447"}, {'M', "57755"}, {'N', "65555"},
    {'O', "25552"}, {'P', "65644"}, {'Q', "25563"}, {'R', "65655"}, {'S', "34216"}, {'T', "72222"},
    {'U', "55557"}, {'V', "55552"}, {'W', "55775"}, {'X', "55255"}, {'Y', "55222"}, {'Z', "71247"},
    {' ', "00000"}, {'.', "00002"}, {',', "00024"}, {'-', "00700"}, {'+', "02720"}, {':', "02020"},
    {'/', "11244"}, {'(', "24442"}, {')', "42224"}, {'%', "51245"}, {'_', "00007"}, {'=', "07070"},
    {'*', "05250"}, {'#', "57575"}, {'?', "71202"},
};
constexpr int tiny_scale = 2, tiny_advance = 4 * tiny_scale;

const char* tiny_glyph(char c) {
    if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    for (const glyph& g : tiny_font)
        if (g.c == c) return g.rows;
    return "71202";  // '?'
}

enum class align { left, center, right };

// Draws text with the tiny font; y is the top of the glyphs. Clipped to the image.
void draw_tiny_text(image& img, int x, int y, const std::string& text, align a, color c) {
    const int text_w = int(text.size()) * tiny_advance - tiny_scale;
    if (a == align::center) x -= text_w / 2;
    if (a == align::right) x -= text_w;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char* rows = tiny_glyph(text[k]);
        for (int r = 0; r < 5 * tiny_scale; ++r)
            for (int s = 0; s < 3 * tiny_scale; ++s) {
                const int bits = rows[r / tiny_scale] - '0';
                if (!(bits & (4 >> (s / tiny_scale)))) continue;
                const int px = x + int(k) * tiny_advance + s, py = y + r;
                if (px >= 0 && px < img.width && py >= 0 && py < img.height) img.at(px, py) = c;
            }
    }
}

// The font for OIIO's render_text: $STRAHL_FONT if set (a missing file there means "use the tiny font"),
// else DejaVu Sans from Debian's fonts-dejavu-core. Empty when none is found.
std::string font_file() {
    if (const char* env = std::getenv("STRAHL_FONT")) {
        std::error_code ec;
        return std::filesystem::is_regular_file(env, ec) ? std::string(env) : std::string();
    }
    for (const char* candidate : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                  "/usr/share/fonts/TTF/DejaVuSans.ttf", "/usr/share/fonts/dejavu/DejaVuSans.ttf"}) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
    return {};
}

struct text_item {
    int x, y;  // anchor: y is the top of the line
    std::string text;
    align a;
};

// Renders the legend's text into rows [y0, img.height) of img: OIIO's render_text with a TrueType font where
// one is found and works, else the tiny font.
void draw_legend_text(image& img, int y0, const std::vector<text_item>& items, int font_px) {
    const color white(1.0f);
    const std::string font = font_file();
    if (!font.empty()) {
        // Render into a float buffer holding the legend strip, then copy it back.
        const int h = img.height - y0;
        OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, h, 3, OIIO::TypeDesc::FLOAT));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < img.width; ++x) buf.setpixel(x, y, &img.at(x, y0 + y)[0], 3);
        bool ok = true;
        for (const text_item& t : items) {
            const auto ax = t.a == align::left    ? OIIO::ImageBufAlgo::TextAlignX::Left
                            : t.a == align::right ? OIIO::ImageBufAlgo::TextAlignX::Right
                                                  : OIIO::ImageBufAlgo::TextAlignX::Center;
            ok = ok && OIIO::ImageBufAlgo::render_text(buf, t.x, t.y - y0, t.text, font_px, font, {1.0f, 1.0f, 1.0f},
                                                       ax, OIIO::ImageBufAlgo::TextAlignY::Top);
        }
        if (ok) {
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < img.width; ++x) buf.getpixel(x, y, &img.at(x, y0 + y)[0], 3);
            return;
        }
        OIIO::geterror();  // render_text failed (font unreadable): clear the message, use the tiny font
        buf.geterror();
    }
    for (const text_item& t : items) draw_tiny_text(img, t.x, t.y, t.text, t.a, white);
}

std::string format_value(float v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.4g", double(v));
    return s;
}

}  // namespace

// Layout below the picture: a gap, the ramp bar, a line with min (left) and max (right), a line with the label.
// Values are mapped linearly from the smallest to the largest finite value; all equal maps to the ramp's start;
// -inf and +inf go to the ends; NaN is drawn magenta. The legend background is black, its text white.
image heat_map(const std::vector<float>& values, int width, int height, const std::string& label) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("heat_map: width and height must be positive");
    if (values.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("heat_map: values.size() must be width * height");

    // Range over the finite values.
    float lo = inf, hi = -inf;
    for (float v : values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (lo > hi) lo = hi = 0.0f;  // no finite value at all
    const double span = double(hi) - double(lo);
    auto to_t = [&](float v) { return span > 0.0 ? float((double(v) - double(lo)) / span) : 0.0f; };

    // Layout of the legend strip.
    constexpr int font_px = 13, line_h = 16, gap = 4, bar_h = 12;
    const int margin = std::min(8, width / 8);
    const int bar_y = height + gap, text1_y = bar_y + bar_h + gap, text2_y = text1_y + line_h;
    image img(width, text2_y + line_h + gap, color(0.0f));

    // The picture.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float v = values[std::size_t(y) * width + x];
            img.at(x, y) = std::isnan(v) ? nan_colour : ramp(v == inf ? 1.0f : v == -inf ? 0.0f : to_t(v));
        }

    // The ramp bar, from min at the left to max at the right.
    const int bar_x0 = margin, bar_x1 = std::max(width - margin, bar_x0 + 1);
    for (int x = bar_x0; x < bar_x1 && x < width; ++x) {
        const float t = bar_x1 - bar_x0 > 1 ? float(x - bar_x0) / float(bar_x1 - bar_x0 - 1) : 0.0f;
        for (int y = bar_y; y < bar_y + bar_h; ++y) img.at(x, y) = ramp(t);
    }

    // The labels.
    draw_legend_text(img, bar_y + bar_h,
                     {{bar_x0, text1_y, format_value(lo), align::left},
                      {bar_x1, text1_y, format_value(hi), align::right},
                      {width / 2, text2_y, label, align::center}},
                     font_px);
    return img;
}

}  // namespace strahl
