/* l_print.c - what a script prints reaches the terminal as text only.
 *
 * A script is untrusted (docs/security.md): print("\27]52;c;...\7") would
 * write the user's clipboard, "\27]0;...\7" the window title, "\27[2J"
 * clear the screen and hide what came before, and some terminals have had
 * worse (escape sequences that answer back as typed input). So everything
 * a script's text reaches stdout or stderr through - print, io.write,
 * lamina.report's lines, error messages - goes out with its control
 * characters written as Lua escapes: the C0 controls but tab and newline,
 * DEL, and the C1 controls in UTF-8 (U+0080..U+009F, C2 80..C2 9F; 0x9B
 * is CSI). Other UTF-8 passes as it is. (issue 31 item 8) */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

void la_write_clean(FILE *f, const char *s, size_t n)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t run = 0;   /* bytes before p[i] not written yet start at i - run */
    for (size_t i = 0; i < n; i++) {
        unsigned c = p[i];
        int c1 = c == 0xc2 && i + 1 < n && p[i + 1] >= 0x80 && p[i + 1] <= 0x9f;
        if ((c >= 0x20 && c != 0x7f && !c1) || c == '\n' || c == '\t') {
            run++;
            continue;
        }
        fwrite(p + i - run, 1, run, f);
        run = 0;
        if (c1) {
            fprintf(f, "\\u{%x}", p[++i]);   /* U+0080..U+009F */
        } else {
            fprintf(f, "\\%u", c);
        }
    }
    fwrite(p + n - run, 1, run, f);
}

/* print(...): as Lua's (tostring of each, tabs between, a newline). */
static int l_print(lua_State *L)
{
    int n = lua_gettop(L);
    for (int i = 1; i <= n; i++) {
        size_t len;
        const char *s = luaL_tolstring(L, i, &len);
        if (i > 1) fputc('\t', stdout);
        la_write_clean(stdout, s, len);
        lua_pop(L, 1);
    }
    fputc('\n', stdout);
    fflush(stdout);
    return 0;
}

void la_open_print(lua_State *L)
{
    lua_register(L, "print", l_print);
}
