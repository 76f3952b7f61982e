/* font.c - the one face lamina draws text with (docs/design.md, "Rendering":
 * one bundled face, hinting off, so that images match across machines).
 *
 * The face is assets/fonts/DejaVuSans.ttf, loaded from its file through
 * cairo's FreeType backend rather than looked up by family name, so a
 * machine's fontconfig setup (other versions of DejaVu, substitution rules,
 * a missing package) cannot change a frame. It is the same file Debian's
 * fonts-dejavu-core installs, so frames drawn before the font was bundled
 * keep their pixels. Both backends draw text through cairo with this face
 * (the OSMesa one rasterises strings with cairo and blends them in GL), so
 * text matches between them too. */
#include "canvas_backend.h"

#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define FONT_FILE "fonts/DejaVuSans.ttf"

static cairo_font_face_t *face;         /* process-wide, made on first use */
static cairo_surface_t *meter_surface;  /* for lr_text_width */
static cairo_t *meter;

static cairo_font_face_t *fallback_face(const char *path)
{
    static int warned;
    if (!warned) {
        fprintf(stderr, "lamina: the bundled font '%s' is missing; drawing "
                "text with the system's DejaVu Sans instead (set LAMINA_ASSETS "
                "to lamina's assets folder)\n", path);
        warned = 1;
    }
    return cairo_toy_font_face_create("DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                                      CAIRO_FONT_WEIGHT_NORMAL);
}

static cairo_font_face_t *bundled_face(void)
{
    if (face)
        return face;
    const char *assets = getenv("LAMINA_ASSETS");
    if (!assets || !*assets)
        assets = LAMINA_ASSETS_DIR;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", assets, FONT_FILE);
    if (access(path, R_OK) == 0) {
        FcPattern *p = FcPatternCreate();
        if (p && FcPatternAddString(p, FC_FILE, (const FcChar8 *)path) &&
            FcPatternAddInteger(p, FC_INDEX, 0))
            face = cairo_ft_font_face_create_for_pattern(p);
        if (p)
            FcPatternDestroy(p);    /* the face keeps its own copy */
        if (face && cairo_font_face_status(face) != CAIRO_STATUS_SUCCESS) {
            cairo_font_face_destroy(face);
            face = NULL;
        }
    }
    if (!face)
        face = fallback_face(path);
    return face;
}

/* Images must match across machines, so nothing may depend on the local
 * setup: no hinting, unhinted metrics, greyscale antialiasing (never
 * subpixel). */
int lr_font_setup(cairo_t *cr)
{
    cairo_font_options_t *fo = cairo_font_options_create();
    if (cairo_font_options_status(fo) != CAIRO_STATUS_SUCCESS) {
        cairo_font_options_destroy(fo);
        return -1;
    }
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    cairo_set_font_face(cr, bundled_face());
    return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : -1;
}

double lr_text_width(double size, const char *text)
{
    if (!text || !*text || !(size > 0))
        return 0.0;
    if (!meter) {
        meter_surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
        meter = cairo_create(meter_surface);
        lr_font_setup(meter);
    }
    char *clean = lr_utf8_clean(text);
    double w = 0.0;
    if (clean && cairo_status(meter) == CAIRO_STATUS_SUCCESS) {
        cairo_text_extents_t e;
        cairo_set_font_size(meter, size);
        cairo_text_extents(meter, clean, &e);
        if (cairo_status(meter) == CAIRO_STATUS_SUCCESS)
            w = e.x_advance;
    }
    free(clean);
    return w;
}

void lr_font_release(void)
{
    cairo_destroy(meter);
    cairo_surface_destroy(meter_surface);
    cairo_font_face_destroy(face);
    meter = NULL;
    meter_surface = NULL;
    face = NULL;
}
