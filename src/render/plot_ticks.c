/* plot_ticks.c - "nice" axis ticks and their labels.
 *
 * Steps are 1, 2 or 5 x 10^k: the values people read off a scale without
 * arithmetic. Tick values are computed as (integer x mantissa) scaled by an
 * exact power of ten, never accumulated, so 0.3 is 0.3 (3/10 rounded once)
 * and not 0.1 + 0.1 + 0.1. */
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A whole number of steps, k * m * 10^e, rounded once. Dividing by 10^-e
 * (exact for the powers used here) rounds better than multiplying by the
 * inexact 10^e when e < 0. "+ 0.0" turns -0.0 (k = -0) into +0.0. */
static double tick_value(double k, int m, int e)
{
    double km = k * m;
    return (e >= 0 ? km * pow(10.0, e) : km / pow(10.0, -e)) + 0.0;
}

int lr_plot_ticks(double lo, double hi, int max_intervals, double *ticks, int cap,
                  double *step)
{
    if (!isfinite(lo) || !isfinite(hi) || !(lo < hi) || max_intervals < 1 ||
        cap < 0 || (cap > 0 && !ticks))
        return -1;
    double span = hi - lo;
    double raw = span / max_intervals;
    if (!isfinite(span) || !(raw > 0))
        return -1;
    /* the smallest of {1, 2, 5, 10} x 10^e not below raw; log10 may be off
     * by an ulp at exact powers of ten, which the 10 case absorbs */
    int e = (int)floor(log10(raw));
    static const int mant[] = { 1, 2, 5, 10 };
    int m = 10;
    for (int i = 0; i < 4; i++)
        if (tick_value(1, mant[i], e) >= raw * (1.0 - 1e-12)) {
            m = mant[i];
            break;
        }
    if (m == 10) {
        m = 1;
        e++;
    }
    double s = tick_value(1, m, e);
    if (!(s > 0) || !isfinite(s))
        return -1;
    double kf = ceil(lo / s - 1e-9), kl = floor(hi / s + 1e-9);
    if (!isfinite(kf) || !isfinite(kl) || fabs(kf) > 9e15 || fabs(kl) > 9e15)
        return -1;   /* k * m would no longer be exact */
    int n = 0;
    for (double k = kf; k <= kl && n < cap; k++)
        ticks[n++] = tick_value(k, m, e);
    if (step)
        *step = s;
    return n;
}

/* Removes trailing zeros of a fraction ("2.50" -> "2.5", "3.00" -> "3"). */
static void strip_fraction(char *s)
{
    if (!strchr(s, '.'))
        return;
    size_t n = strlen(s);
    while (n > 0 && s[n - 1] == '0')
        s[--n] = '\0';
    if (n > 0 && s[n - 1] == '.')
        s[--n] = '\0';
}

/* The same for a mantissa: "2.50e+05" -> "2.5e+05", "1.0e-05" -> "1e-05". */
static void strip_mantissa(char *s)
{
    char *e = strchr(s, 'e');
    if (!e)
        return;
    char exp[LR_TICK_LABEL_MAX];
    snprintf(exp, sizeof exp, "%s", e);
    *e = '\0';
    strip_fraction(s);
    size_t n = strlen(s);
    snprintf(s + n, LR_TICK_LABEL_MAX - n, "%s", exp);
}

/* floor(log10(v)) for v > 0, robust to log10 landing an ulp below an
 * exact power of ten. */
static int decade(double v)
{
    return (int)floor(log10(v) + 1e-9);
}

void lr_plot_tick_labels(const double *ticks, int n, double step,
                         char (*labels)[LR_TICK_LABEL_MAX])
{
    if (!ticks || !labels || n <= 0)
        return;
    double maxabs = 0.0;
    for (int i = 0; i < n; i++)
        if (isfinite(ticks[i]))
            maxabs = fmax(maxabs, fabs(ticks[i]));
    /* the place of the step's last significant digit: 10^-3 for 0.005,
     * and also for a step of 0.0025 given by a caller (1 digit more) */
    int se = 0;
    if (step > 0 && isfinite(step)) {
        se = decade(step);
        for (int extra = 0; extra <= 3; extra++) {
            double v = step / pow(10.0, se - extra);
            if (fabs(v - round(v)) < 1e-6 * v) {
                se -= extra;
                break;
            }
        }
    }
    int sci = maxabs >= 1e5 || (step > 0 && step < 1e-4);
    for (int i = 0; i < n; i++) {
        char *s = labels[i];
        double v = ticks[i];
        if (!isfinite(v)) {
            snprintf(s, LR_TICK_LABEL_MAX, "%s", isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
            continue;
        }
        if (v == 0.0) {
            snprintf(s, LR_TICK_LABEL_MAX, "0");
            continue;
        }
        if (sci) {
            /* as many mantissa digits as tell neighbouring ticks apart */
            int d = (maxabs > 0 ? decade(maxabs) : 0) - se;
            d = d < 0 ? 0 : d > 16 ? 16 : d;
            snprintf(s, LR_TICK_LABEL_MAX, "%.*e", d, v);
            strip_mantissa(s);
        } else {
            int d = se < 0 ? -se : 0;
            d = d > 16 ? 16 : d;
            snprintf(s, LR_TICK_LABEL_MAX, "%.*f", d, v);
            strip_fraction(s);
        }
        /* a tiny value rounded away: zero, without its sign */
        if (strcmp(s, "-0") == 0)
            snprintf(s, LR_TICK_LABEL_MAX, "0");
    }
}
