/* l_analysis_period.c - lamina.analysis.period and .frequency: the period
 * of a recorded series (t, y), e.g. rec:column("t"), rec:column("y").
 *
 *   local T, cycles = lamina.analysis.period(t, y)                     -- crossings
 *   local T, cycles = lamina.analysis.period(t, y, {method = "dft"})
 *   local f, cycles = lamina.analysis.frequency(t, y, {from = 0.1, to = 2})
 *
 * "crossings" (default): the mean time between upward crossings of a level,
 * each found by linear interpolation between its two samples. The level is
 * `level` when given; else the series' mean over whole cycles: first the
 * mean of all samples, then the time average (trapezoids) between the
 * first and the last upward crossing of it, and the crossings of that -
 * for a sinusoid about any offset that is its centre line, where it is
 * straightest, so the interpolation error is smallest. Needs two upward
 * crossings.
 *
 * "dft": the peak of the windowed discrete-time Fourier transform,
 * |sum_i dt_i w_i (y_i - mean) exp(-2 pi i f t_i)| with the Hann window w
 * over [t_first, t_last] and trapezoid weights dt_i (any spacing). The
 * largest bin of an FFT of the series resampled uniformly and zero-padded
 * eight times finds the peak; golden-section search on the transform of
 * the samples themselves then places it. The window's leakage from the
 * negative frequency biases the peak by a little, less the more cycles the
 * series holds (docs/api.md gives the accuracy the tests measure).
 *
 * Both return the period (or frequency) and the cycles it rests on
 * (crossings: their count - 1; dft: f times the window's length); nil and
 * why when the series has none (fewer than two crossings, a constant). */
#include <math.h>
#include <string.h>

#include "l_analysis.h"

#define TWO_PI 6.283185307179586476925286766559

typedef struct series {
    const double *t, *y;
    size_t n;
} series;

/* The samples with from <= t <= to. */
static series window_of(lua_State *L, const char *fn, int opts)
{
    size_t n = 0, ny = 0;
    const double *t = la_analysis_array(L, 1, fn, "t", &n);
    const double *y = la_analysis_array(L, 2, fn, "y", &ny);
    if (ny != n) luaL_error(L, "%s: t has %d values, y %d", fn, (int)n, (int)ny);
    for (size_t i = 1; i < n; i++)
        if (!(t[i] > t[i - 1]))
            luaL_error(L, "%s: t must increase (t[%d] = %f after t[%d] = %f)", fn, (int)i + 1,
                       t[i], (int)i, t[i - 1]);
    double from = opts ? la_opt_number(L, opts, fn, "from", -HUGE_VAL) : -HUGE_VAL;
    double to = opts ? la_opt_number(L, opts, fn, "to", HUGE_VAL) : HUGE_VAL;
    if (!(from < to)) luaL_error(L, "%s: 'from' (%f) must be below 'to' (%f)", fn, from, to);
    size_t a = 0, b = n;
    while (a < n && t[a] < from) a++;
    while (b > a && t[b - 1] > to) b--;
    if (b - a < 3)
        luaL_error(L, "%s: %d samples in [%f, %f]; at least 3 are needed", fn, (int)(b - a),
                   n ? fmax(from, t[0]) : from, n ? fmin(to, t[n - 1]) : to);
    series s = {t + a, y + a, b - a};
    return s;
}

/* Upward crossings of level: the first and last time and their count. */
static size_t crossings(const series *s, double level, double *first, double *last,
                        size_t *i_first, size_t *i_last)
{
    size_t k = 0;
    for (size_t i = 1; i < s->n; i++) {
        double a = s->y[i - 1] - level, b = s->y[i] - level;
        if (a < 0 && b >= 0) {
            double tc = s->t[i - 1] + (s->t[i] - s->t[i - 1]) * (-a) / (b - a);
            if (k == 0) {
                *first = tc;
                *i_first = i;
            }
            *last = tc;
            *i_last = i;
            k++;
        }
    }
    return k;
}

/* The time average of y over [ta, tb] (ta in the sample interval ending at
 * ia, tb in the one ending at ib), by trapezoids on the interpolant. */
static double mean_between(const series *s, double ta, size_t ia, double tb, size_t ib)
{
    double sum = 0, ya, yb;
    #define AT(tt, i) (s->y[(i) - 1] + (s->y[i] - s->y[(i) - 1]) * \
                       ((tt) - s->t[(i) - 1]) / (s->t[i] - s->t[(i) - 1]))
    ya = AT(ta, ia);
    yb = AT(tb, ib);
    #undef AT
    if (ia == ib) return 0.5 * (ya + yb);
    sum += 0.5 * (ya + s->y[ia]) * (s->t[ia] - ta);
    for (size_t i = ia + 1; i < ib; i++)
        sum += 0.5 * (s->y[i - 1] + s->y[i]) * (s->t[i] - s->t[i - 1]);
    sum += 0.5 * (s->y[ib - 1] + yb) * (tb - s->t[ib - 1]);
    return sum / (tb - ta);
}

static int by_crossings(lua_State *L, const char *fn, const series *s, int opts,
                        double *period, double *cycles)
{
    double first = 0, last = 0, level;
    size_t ia = 0, ib = 0, k;
    if (opts && la_has(L, opts, "level")) {
        level = la_opt_number(L, opts, fn, "level", 0);
        k = crossings(s, level, &first, &last, &ia, &ib);
    } else {
        level = 0;
        for (size_t i = 0; i < s->n; i++) level += s->y[i];
        level /= (double)s->n;
        k = crossings(s, level, &first, &last, &ia, &ib);
        if (k >= 2) {   /* the mean over whole cycles, and its crossings */
            level = mean_between(s, first, ia, last, ib);
            k = crossings(s, level, &first, &last, &ia, &ib);
        }
    }
    if (k < 2) {
        lua_pushnil(L);
        lua_pushfstring(L, "%s: %d upward crossing%s of the level %f in [%f, %f]: two are "
                        "needed", fn, (int)k, k == 1 ? "" : "s", level, s->t[0],
                        s->t[s->n - 1]);
        return -1;
    }
    *period = (last - first) / (double)(k - 1);
    *cycles = (double)(k - 1);
    return 0;
}

/* In-place radix-2 FFT of re + i im, m a power of two (forward). */
static void fft(double *re, double *im, size_t m)
{
    for (size_t i = 1, j = 0; i < m; i++) {   /* bit reversal */
        size_t bit = m >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            double t = re[i]; re[i] = re[j]; re[j] = t;
            t = im[i]; im[i] = im[j]; im[j] = t;
        }
    }
    for (size_t len = 2; len <= m; len <<= 1) {
        double ang = -TWO_PI / (double)len;
        for (size_t i = 0; i < m; i += len) {
            for (size_t k = 0; k < len / 2; k++) {
                double wr = cos(ang * (double)k), wi = sin(ang * (double)k);
                double *ar = re + i + k, *ai = im + i + k;
                double *br = re + i + k + len / 2, *bi = im + i + k + len / 2;
                double xr = *br * wr - *bi * wi, xi = *br * wi + *bi * wr;
                *br = *ar - xr;
                *bi = *ai - xi;
                *ar += xr;
                *ai += xi;
            }
        }
    }
}

/* |windowed transform|^2 of the samples at frequency f; v holds
 * dt_i w_i (y_i - mean). */
static double power(const series *s, const double *v, double f)
{
    double re = 0, im = 0;
    for (size_t i = 0; i < s->n; i++) {
        double ph = -TWO_PI * f * (s->t[i] - s->t[0]);
        re += v[i] * cos(ph);
        im += v[i] * sin(ph);
    }
    return re * re + im * im;
}

static int by_dft(lua_State *L, const char *fn, const series *s, double *period,
                  double *cycles)
{
    size_t n = s->n;
    double t0 = s->t[0], span = s->t[n - 1] - t0;
    /* trapezoid weights, the mean, and the windowed samples */
    double *v = la_analysis_scratch(L, n);
    double mean = 0;
    for (size_t i = 0; i < n; i++) {
        double dt = 0.5 * ((i + 1 < n ? s->t[i + 1] : s->t[i]) - (i ? s->t[i - 1] : s->t[i]));
        v[i] = dt;
        mean += dt * s->y[i];
    }
    mean /= span;
    double amp = 0;
    for (size_t i = 0; i < n; i++) {
        double w = 0.5 * (1 - cos(TWO_PI * (s->t[i] - t0) / span));
        v[i] *= w * (s->y[i] - mean);
        amp = fmax(amp, fabs(s->y[i] - mean));
    }
    if (!(amp > 0)) {
        lua_pushnil(L);
        lua_pushfstring(L, "%s: the series is constant in [%f, %f]: no period", fn, t0,
                        s->t[n - 1]);
        return -1;
    }
    /* the coarse peak: resampled uniformly (n points), zero-padded to m */
    size_t m = 1;
    while (m < 8 * n) m <<= 1;
    double *re = la_analysis_scratch(L, m), *im = la_analysis_scratch(L, m);
    memset(re, 0, m * sizeof *re);
    memset(im, 0, m * sizeof *im);
    double h = span / (double)(n - 1);
    for (size_t k = 0, i = 1; k < n; k++) {
        double tk = t0 + h * (double)k;
        while (i < n - 1 && s->t[i] < tk) i++;
        double a = (tk - s->t[i - 1]) / (s->t[i] - s->t[i - 1]);
        double y = s->y[i - 1] + a * (s->y[i] - s->y[i - 1]);
        re[k] = 0.5 * (1 - cos(TWO_PI * (double)k / (double)(n - 1))) * (y - mean);
    }
    fft(re, im, m);
    size_t best = 1;
    for (size_t k = 2; k <= m / 2; k++)
        if (re[k] * re[k] + im[k] * im[k] > re[best] * re[best] + im[best] * im[best])
            best = k;
    double df = 1 / (h * (double)m);
    /* golden section on the samples' own transform, one bin either side */
    double lo = fmax((double)best - 1, 0.5) * df, hi = ((double)best + 1) * df;
    const double g = (sqrt(5.0) - 1) / 2;
    double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    double pa = power(s, v, a), pb = power(s, v, b);
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
        if (pa < pb) {
            lo = a;
            a = b;
            pa = pb;
            b = lo + g * (hi - lo);
            pb = power(s, v, b);
        } else {
            hi = b;
            b = a;
            pb = pa;
            a = hi - g * (hi - lo);
            pa = power(s, v, a);
        }
    }
    double f = 0.5 * (lo + hi);
    *period = 1 / f;
    *cycles = f * span;
    return 0;
}

static int measure(lua_State *L, const char *fn, int invert)
{
    static const char *const keys[] = {"method", "level", "from", "to", NULL};
    static const char *const methods[] = {"crossings", "dft", NULL};
    int opts = 0;
    if (!lua_isnoneornil(L, 3)) {
        la_check_keys(L, 3, fn, keys);
        opts = 3;
    }
    const char *method = opts ? la_opt_string(L, 3, fn, "method", "crossings") : "crossings";
    int which = la_option(L, fn, "method", method, methods);
    if (which == 1 && opts && la_has(L, 3, "level"))
        return luaL_error(L, "%s: 'level' is for method = \"crossings\"", fn);
    series s = window_of(L, fn, opts);
    double period = 0, cycles = 0;
    int rc = which == 0 ? by_crossings(L, fn, &s, opts, &period, &cycles)
                        : by_dft(L, fn, &s, &period, &cycles);
    if (rc != 0) return 2;   /* nil, why */
    lua_pushnumber(L, invert ? 1 / period : period);
    lua_pushnumber(L, cycles);
    return 2;
}

int la_analysis_period(lua_State *L)
{
    return measure(L, "lamina.analysis.period", 0);
}

int la_analysis_frequency(lua_State *L)
{
    return measure(L, "lamina.analysis.frequency", 1);
}
