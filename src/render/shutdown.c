/* shutdown.c - releasing the libraries' process-wide caches at exit.
 *
 * cairo keeps font faces and fontconfig its configuration for the life of
 * the process; freeing them at exit (as cairo's own test suite does) keeps
 * valgrind's leak report about lamina's memory only. */
#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include "canvas_backend.h"
#include "render.h"

void lr_shutdown(void)
{
    lr_canvas_gl_release();     /* the GL contexts kept for reuse, EGL's display */
    lr_font_release();      /* lamina's cached face first: cairo's reset frees what it held */
    cairo_debug_reset_static_data();
    FcFini();
}
