/* l_provenance.c - what every image lamina writes says about itself, and
 * the note of where the run's images went (docs/design.md, "Provenance"). */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

/* The --set parameters as one line, "name=value name=value"; pushed on the
 * stack, where it must stay while the returned string is used. */
static const char *push_set_line(lua_State *L, const lamina_run *run)
{
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 0; run && i < run->nsets; i++) {
        if (i) luaL_addchar(&b, ' ');
        luaL_addstring(&b, run->sets[i].name);
        luaL_addchar(&b, '=');
        luaL_addstring(&b, run->sets[i].value);
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

void la_provenance(lua_State *L, la_prov *p)
{
    const lamina_run *run = la_run(L);
    snprintf(p->version, sizeof p->version, "lamina %s", LAMINA_VERSION);
    snprintf(p->hash, sizeof p->hash, "%s", run ? run->script_hash : "");
    p->text[0].key = "Software";
    p->text[0].value = p->version;
    p->text[1].key = "lamina:script";
    p->text[1].value = run && run->script ? run->script : "";
    p->text[2].key = "lamina:script-hash";
    p->text[2].value = p->hash;
    p->text[3].key = "lamina:set";
    p->text[3].value = push_set_line(L, run);
}

/* Counts the image and keeps its folder for `lamina run`'s closing line. */
void la_note_image(lua_State *L, const char *path)
{
    lamina_run *run = la_run(L);
    if (!run) return;
    run->frames++;
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) + 1 : 0;
    if (n >= sizeof run->frame_dir) n = sizeof run->frame_dir - 1;
    memcpy(run->frame_dir, path, n);
    run->frame_dir[n] = 0;
    if (n == 0) strcpy(run->frame_dir, "./");
    if (run->observer && run->observer->image) run->observer->image(run->observer->ud, path);
}
