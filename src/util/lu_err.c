/* lu_err.c - error messages into a caller's buffer (util.h). */
#include "util.h"

#include <stdio.h>

void lu_verr(char *err, size_t errlen, const char *fmt, va_list ap)
{
    if (!err || errlen == 0)
        return;
    vsnprintf(err, errlen, fmt, ap);
}

void lu_err(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    lu_verr(err, errlen, fmt, ap);
    va_end(ap);
}
