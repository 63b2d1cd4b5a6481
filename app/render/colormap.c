/* Perceptually uniform colour maps built in OKLab (B. Ottosson, "A perceptual color space for
 * image processing", 2020; the matrices below are the ones published there). Lightness varies
 * linearly along each map; hue and chroma follow smooth paths; colours outside the sRGB gamut
 * are brought in by reducing chroma only, so lightness stays exact. */
#include "colormap.h"
#include "drawlist.h"

#include <math.h>
#include <pthread.h>

#define LUT_N 256

static float lut[2][LUT_N][3];
static pthread_once_t lut_once = PTHREAD_ONCE_INIT;

static double srgb_encode(double x) { /* linear -> sRGB transfer */
    if (x <= 0.0031308) return 12.92 * x;
    return 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static double srgb_decode(double x) {
    if (x <= 0.04045) return x / 12.92;
    return pow((x + 0.055) / 1.055, 2.4);
}

static void oklab_to_linear(double L, double a, double b, double rgb[3]) {
    double l_ = L + 0.3963377774 * a + 0.2158037573 * b;
    double m_ = L - 0.1055613458 * a - 0.0638541728 * b;
    double s_ = L - 0.0894841775 * a - 1.2914855480 * b;
    double l = l_ * l_ * l_, m = m_ * m_ * m_, s = s_ * s_ * s_;
    rgb[0] = 4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s;
    rgb[1] = -1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s;
    rgb[2] = -0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s;
}

void pl_srgb_to_oklab(const pl_rgba *c, double lab[3]) {
    double r = srgb_decode(c->r), g = srgb_decode(c->g), b = srgb_decode(c->b);
    double l = 0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b;
    double m = 0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b;
    double s = 0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b;
    double l_ = cbrt(l), m_ = cbrt(m), s_ = cbrt(s);
    lab[0] = 0.2104542553 * l_ + 0.7936177850 * m_ - 0.0040720468 * s_;
    lab[1] = 1.9779984951 * l_ - 2.4285922050 * m_ + 0.4505937099 * s_;
    lab[2] = 0.0259040371 * l_ + 0.7827717662 * m_ - 0.8086757660 * s_;
}

static int in_gamut(const double rgb[3]) {
    const double eps = 1e-9;
    return rgb[0] >= -eps && rgb[0] <= 1 + eps && rgb[1] >= -eps && rgb[1] <= 1 + eps &&
           rgb[2] >= -eps && rgb[2] <= 1 + eps;
}

/* OKLCh (hue in degrees) -> sRGB, reducing chroma until the colour is displayable. */
static void lch_to_srgb(double L, double C, double h_deg, float out[3]) {
    double h = h_deg * (3.14159265358979323846 / 180.0);
    double ca = cos(h), sa = sin(h), rgb[3];
    oklab_to_linear(L, C * ca, C * sa, rgb);
    if (!in_gamut(rgb)) {
        double lo = 0.0, hi = C;
        for (int it = 0; it < 40; it++) {
            double mid = 0.5 * (lo + hi);
            oklab_to_linear(L, mid * ca, mid * sa, rgb);
            if (in_gamut(rgb)) lo = mid;
            else hi = mid;
        }
        oklab_to_linear(L, lo * ca, lo * sa, rgb);
    }
    for (int k = 0; k < 3; k++) {
        double v = rgb[k] < 0.0 ? 0.0 : (rgb[k] > 1.0 ? 1.0 : rgb[k]);
        out[k] = (float)srgb_encode(v);
    }
}

static void build_luts(void) {
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < LUT_N; i++) {
        double t = (double)i / (LUT_N - 1);
        /* Sequential: L 0.30 -> 0.94, hue 295 (violet) -> 105 (yellow), chroma dipping
         * slightly through the blue-green middle like viridis. */
        double L = 0.30 + 0.64 * t;
        double h = 295.0 - 190.0 * t;
        double C = 0.135 - 0.035 * sin(pi * t) + 0.045 * t * t;
        lch_to_srgb(L, C, h, lut[PL_CMAP_SEQUENTIAL][i]);
        /* Diverging: blue (hue 255) -> near white -> red (hue 28), lightness symmetric. */
        double u = fabs(2.0 * t - 1.0);
        double Ld = 0.96 - 0.52 * u;
        double Cd = 0.012 + 0.14 * u;
        lch_to_srgb(Ld, Cd, t < 0.5 ? 255.0 : 28.0, lut[PL_CMAP_DIVERGING][i]);
    }
}

pl_rgba pl_colormap_eval(pl_colormap map, double t) {
    pthread_once(&lut_once, build_luts);
    if (map != PL_CMAP_DIVERGING) map = PL_CMAP_SEQUENTIAL;
    if (isnan(t)) return pl_rgb(0.5, 0.5, 0.5);
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    double x = t * (LUT_N - 1);
    int i = (int)x;
    if (i >= LUT_N - 1) i = LUT_N - 2;
    double f = x - i;
    const float *a = lut[map][i], *b = lut[map][i + 1];
    return pl_rgb(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
}

pl_rgba pl_colormap_value(pl_colormap map, double v, double vmin, double vmax) {
    double d = vmax - vmin;
    double t = d > 0.0 ? (v - vmin) / d : 0.5;
    return pl_colormap_eval(map, t);
}

pl_rgba pl_material_palette(int index) {
    static const uint32_t pal[] = {
        0xE2B86E, /* sand */
        0x86AED6, /* soft blue */
        0xA0C98C, /* sage */
        0xDD907A, /* terracotta */
        0xB7A2DC, /* lavender */
        0x7FCAC3, /* teal */
        0xE8A6C6, /* pink */
        0xCFC7A1  /* khaki */
    };
    const int n = (int)(sizeof pal / sizeof pal[0]);
    if (index < 0) index = -index;
    return pl_rgb_hex(pal[index % n]);
}
