/* l_checkpoint.c - sim:checkpoint{file, every | at} and restarting a run
 * from one with `lamina run SCRIPT --restart FILE` (docs/api.md).
 *
 * Semantics: the script runs again from the top and builds its objects as
 * before; at the first sim:run/sim:step of the simulation the checkpoint
 * was taken from (the n-th lamina.sim the script makes), its state is
 * replaced by the checkpoint's — particles, clock, live settings,
 * materials, pins, and each recorder's rows — and the run continues from
 * the checkpoint's time. Callbacks and records that were due at or before
 * it do not fire again. Lua's own variables are not restored; --set values
 * may differ (a longer t_end).
 *
 * A checkpoint is written after every callback of its step has run, so it
 * holds what they did. The file: a text header, a blank line, the engine's
 * state (checkpoint.c), then each recorder's columns, rows and values. It
 * is written whole or not at all. */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
#include "l_internal.h"
#include "l_sim3.h"
#include "mpm3_membrane.h"

#define MAGIC_LINE "LAMINA-CHECKPOINT"
/* the largest checkpoint read back: 64 GiB, far above any documented use;
 * a file claiming more is refused before anything is allocated */
#define MAX_BYTES ((uint64_t)1 << 36)

/* Either engine's clock: a 3D run (lamina.sim{dim = 3}, l_sim3.h) is
 * checkpointed in the same file layout with its own engine part
 * (sim3_state.c). */
static double ck_t(const la_sim *s) { return s->s3 ? s->s3->sim->t : s->sim->t; }
static double ck_dt(const la_sim *s) { return s->s3 ? s->s3->sim->def.dt : s->sim->def.dt; }
static long ck_step(const la_sim *s) { return s->s3 ? s->s3->sim->nstep : s->sim->step; }

int la_sim_checkpoint(lua_State *L)
{
    static const char *const keys[] = {"file", "every", "at", NULL};
    const char *fn = "sim:checkpoint";
    la_sim *s = la_check_sim_any(L, 1);
    la_check_keys(L, 2, fn, keys);
    /* the points' affine velocities (src/mpm/apic.c) are not in the state */
    if (!s->s3 && s->sim->def.apic)
        return luaL_error(L, "%s: a sim with transfer = \"apic\" cannot be checkpointed (its "
                          "points' affine velocities are not in the state); use transfer = \"flip\"",
                          fn);
    if (la_getfield(L, 2, "file") == LUA_TNIL) return luaL_error(L, "%s: 'file' is required", fn);
    /* a string, no NUL, confined as every output is (l_path.c) */
    const char *file = la_check_output_path(L, fn, -1);
    size_t len = strlen(file);
    int has_every = la_has(L, 2, "every"), has_at = la_has(L, 2, "at");
    if (has_every == has_at) return luaL_error(L, "%s: give exactly one of 'every' and 'at'", fn);
    double every = has_every ? la_number(L, 2, fn, "every") : 0;
    double at = has_at ? la_number(L, 2, fn, "at") : 0;
    if (has_every) la_check_interval(L, fn, "every", every, ck_t(s));
    if (has_at && !isfinite(at)) return luaL_error(L, "%s: at must be a finite time", fn);
    char *copy = malloc(len + 1);
    if (!copy) return luaL_error(L, "%s: out of memory", fn);
    memcpy(copy, file, len + 1);
    free(s->ck_file);
    s->ck_file = copy;
    s->ck_every = every;
    s->ck_next = has_every ? ck_t(s) + every : at;
    return 0;
}

/* Writes the checkpoint of the sim at sidx now. */
static void write_checkpoint(lua_State *L, int sidx, la_sim *s)
{
    size_t eb = s->s3 ? lm3_state_bytes(s->s3->sim) : lm_sim_state_bytes(s->sim);
    int nrec = la_record_count(L, sidx);
    size_t rb = 0;
    for (int i = 1; i <= nrec; i++) {
        int nc;
        size_t nr;
        const double *rows;
        la_record_rows(L, sidx, i, &nc, &nr, &rows);
        rb += sizeof(uint32_t) + sizeof(uint64_t) + nr * (size_t)nc * sizeof(double);
    }
    char head[256];
    int hl = snprintf(head, sizeof head, "%s %d\nsim %d\nt %.17g\nstep %ld\nengine %zu\n"
                      "recorders %d\n\n", MAGIC_LINE, LM_CHECKPOINT_VERSION, s->index,
                      ck_t(s), ck_step(s), eb, nrec);
    size_t total = (size_t)hl + eb + rb;
    unsigned char *buf = malloc(total);
    if (!buf) luaL_error(L, "sim:checkpoint: out of memory for %zu bytes", total);
    memcpy(buf, head, (size_t)hl);
    if (s->s3) lm3_state_save(s->s3->sim, buf + hl);
    else lm_sim_state_save(s->sim, buf + hl);
    unsigned char *b = buf + hl + eb;
    for (int i = 1; i <= nrec; i++) {
        int nc;
        size_t nr;
        const double *rows;
        la_record_rows(L, sidx, i, &nc, &nr, &rows);
        uint32_t c = (uint32_t)nc;
        uint64_t r = nr;
        memcpy(b, &c, sizeof c);
        b += sizeof c;
        memcpy(b, &r, sizeof r);
        b += sizeof r;
        if (nr) memcpy(b, rows, nr * (size_t)nc * sizeof(double));
        b += nr * (size_t)nc * sizeof(double);
    }
    char err[600];
    int rc = lr_write_file(s->ck_file, buf, total, err, sizeof err);
    free(buf);
    if (rc) {   /* the run's failure (l_run_guard.c): the records are still written */
        la_fail_raisef(L, LAMINA_FAIL_IO, "sim:checkpoint: %s", err);
    }
}

void la_checkpoint_due(lua_State *L, int sidx, la_sim *s)
{
    if (!s->ck_file || !(s->ck_next <= ck_t(s) + 0.5 * ck_dt(s))) return;
    write_checkpoint(L, sidx, s);
    if (s->ck_every > 0) {
        /* the next multiple after now, as events do: no bursts; computed,
         * not counted (every = 1e-300 looped for ever, issue 31) */
        double k = 0;
        s->ck_next = la_next_multiple(s->ck_next, s->ck_every, &k,
                                      ck_t(s) + 0.5 * ck_dt(s));
    } else {
        s->ck_next = INFINITY;
    }
}

/* The largest recorders' part read back (their rows): 4 GiB of doubles. */
#define MAX_RECORD_BYTES ((uint64_t)1 << 32)

static int parse_header(const unsigned char *buf, size_t len, int *version, int *sim,
                        uint64_t *eb, int *nrec, size_t *off);

/* What the first bytes of a checkpoint say, checked against the file
 * before anything large is read (issue 31: a sparse 64 GiB file was read
 * whole, a FIFO blocked): a regular file (opened without blocking), its
 * text header, the engine part's size as the engine's own header claims it
 * (lm_sim_state_claimed) equal to the text's, and the recorders' blocks
 * (read one header at a time) ending exactly at the end of the file. Then
 * the whole file, now of a consistent size, into *buf. 0, or -1 with msg. */
static int read_checkpoint(const char *path, int dim3, unsigned char **buf, size_t *len,
                           size_t *off, int *version, int *sim, uint64_t *eb, int *nrec,
                           char *msg, size_t ml)
{
    *buf = NULL;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    if (fd < 0) {
        snprintf(msg, ml, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || (uint64_t)st.st_size > MAX_BYTES) {
        snprintf(msg, ml, "'%s' is not a regular file of at most 64 GiB", path);
        close(fd);
        return -1;
    }
    uint64_t size = (uint64_t)st.st_size;
    unsigned char head[4096];
    ssize_t got = pread(fd, head, sizeof head, 0);
    if (got < 0 || !parse_header(head, (size_t)got, version, sim, eb, nrec, off)) {
        snprintf(msg, ml, "'%s' is not a lamina checkpoint", path);
        close(fd);
        return -1;
    }
    if (*version != LM_CHECKPOINT_VERSION) {   /* the caller says which */
        close(fd);
        return 0;
    }
    unsigned char eh[512];
    got = pread(fd, eh, sizeof eh, (off_t)*off);
    size_t claimed = got <= 0 ? 0
                     : dim3   ? lm3_state_claimed(eh, (size_t)got)
                              : lm_sim_state_claimed(eh, (size_t)got);
    size_t other = got <= 0 ? 0
                   : dim3   ? lm_sim_state_claimed(eh, (size_t)got)
                            : lm3_state_claimed(eh, (size_t)got);
    if (claimed == 0 && other != 0) {   /* the other dimension's: say so */
        snprintf(msg, ml, "'%s' is a checkpoint of a %s simulation; the script's is %s", path,
                 dim3 ? "2D" : "3D", dim3 ? "3D" : "2D");
        close(fd);
        return -1;
    }
    if (claimed == 0 || claimed != *eb || *eb > size - *off) {
        snprintf(msg, ml, "'%s' is %s: its header gives %" PRIu64 " bytes of state, the "
                 "state's own header %zu, the file has %" PRIu64 " after the header", path,
                 *eb > size - *off ? "truncated" : "damaged", *eb, claimed, size - *off);
        close(fd);
        return -1;
    }
    uint64_t at = *off + *eb, rec = 0;
    for (int i = 0; i < *nrec; i++) {
        unsigned char rh[12];
        uint32_t c;
        uint64_t r;
        if (size - at < sizeof rh || pread(fd, rh, sizeof rh, (off_t)at) != (ssize_t)sizeof rh)
            goto damaged;
        memcpy(&c, rh, sizeof c);
        memcpy(&r, rh + sizeof c, sizeof r);
        at += sizeof rh;
        if (c == 0 || r > (size - at) / ((uint64_t)c * sizeof(double))) goto damaged;
        at += r * c * sizeof(double);
        rec += r * c * sizeof(double);
        if (rec > MAX_RECORD_BYTES) {
            snprintf(msg, ml, "'%s': its recorders hold more than 4 GiB of rows", path);
            close(fd);
            return -1;
        }
    }
    if (at != size) goto damaged;
    *buf = malloc(size ? (size_t)size : 1);
    if (!*buf || pread(fd, *buf, (size_t)size, 0) != (ssize_t)size) {
        snprintf(msg, ml, "cannot read '%s' (%" PRIu64 " bytes)", path, size);
        free(*buf);
        *buf = NULL;
        close(fd);
        return -1;
    }
    close(fd);
    *len = (size_t)size;
    return 0;
damaged:
    snprintf(msg, ml, "'%s' is truncated or damaged: its recorders' blocks do not end at the "
             "end of the file (%" PRIu64 " bytes)", path, size);
    close(fd);
    return -1;
}

/* The text header: fills version, sim index, engine bytes, recorder count
 * and *off, the offset of the binary part; 0 if it is not one of ours. */
static int parse_header(const unsigned char *buf, size_t len, int *version, int *sim,
                        uint64_t *eb, int *nrec, size_t *off)
{
    const unsigned char *end = NULL;
    for (size_t i = 0; i + 1 < len && i < 512; i++)
        if (buf[i] == '\n' && buf[i + 1] == '\n') {
            end = buf + i + 2;
            break;
        }
    if (!end) return 0;
    char head[520];
    size_t hl = (size_t)(end - buf);
    memcpy(head, buf, hl);
    head[hl] = 0;
    double t;
    long step;
    if (sscanf(head, MAGIC_LINE " %d\nsim %d\nt %lf\nstep %ld\nengine %" SCNu64 "\nrecorders %d\n",
               version, sim, &t, &step, eb, nrec) != 6 || *nrec < 0 || *nrec > 1 << 20)
        return 0;
    *off = hl;
    return 1;
}

void la_checkpoint_restore(lua_State *L, int sidx, la_sim *s)
{
    lamina_run *run = la_run(L);
    if (!run || !run->restart || run->restored) return;
    if (!s->s3)
        la_ref_capture(L, s);   /* the script's build, before any state is replaced: the
                                   first run's reference positions (l_ref.c) */
    char msg[900];
    size_t len = 0, off = 0;
    unsigned char *buf;
    int version = 0, index = 0, nrec = 0;
    uint64_t eb = 0;
    if (read_checkpoint(run->restart, s->s3 != NULL, &buf, &len, &off, &version, &index, &eb,
                        &nrec, msg, sizeof msg) != 0)
        luaL_error(L, "--restart: %s", msg);
    if (version != LM_CHECKPOINT_VERSION) {
        free(buf);
        luaL_error(L, "--restart: '%s' is checkpoint format %d; this lamina %s reads format %d",
                   run->restart, version, LAMINA_VERSION, LM_CHECKPOINT_VERSION);
    }
    if (index != s->index) {   /* another sim of the script: not this one */
        free(buf);
        return;
    }
    run->restored = 1;
    if (eb > len - off || nrec != la_record_count(L, sidx)) {
        free(buf);
        luaL_error(L, "--restart: '%s' does not fit the script: %s", run->restart,
                   eb > len - off ? "it is truncated" : "its recorders differ");
    }
    if (s->s3 ? lm3_state_load(s->s3->sim, buf + off, (size_t)eb) != LM_OK
              : lm_sim_state_load(s->sim, buf + off, (size_t)eb) != LM_OK) {
        free(buf);
        luaL_error(L, "--restart: '%s': %s", run->restart, s->s3 ? s->s3->sim->err : s->sim->err);
    }
    const unsigned char *b = buf + off + eb, *stop = buf + len;
    for (int i = 1; i <= nrec; i++) {
        uint32_t c;
        uint64_t r;
        if ((size_t)(stop - b) < sizeof c + sizeof r) goto truncated;
        memcpy(&c, b, sizeof c);
        b += sizeof c;
        memcpy(&r, b, sizeof r);
        b += sizeof r;
        if (c == 0 || r > (uint64_t)(stop - b) / (c * sizeof(double))) goto truncated;
        double *rows = malloc(r ? r * c * sizeof(double) : 1);
        if (!rows) goto truncated;
        memcpy(rows, b, r * c * sizeof(double));   /* aligned copy of the values */
        b += r * c * sizeof(double);
        int bad = la_record_set_rows(L, sidx, i, (int)c, (size_t)r, rows);
        free(rows);
        if (bad) {
            free(buf);
            luaL_error(L, "--restart: '%s' does not fit the script: recorder %d has other "
                       "columns", run->restart, i);
        }
    }
    free(buf);
    if (!s->s3) la_material_sync(L, sidx);   /* the script's materials take the restored values */
    /* Say where the run goes on from (issue 35 item 5): without it a
     * restarted run looks like a fresh one. */
    if (!run->quiet)
        fprintf(stderr, "lamina: resumed %s at t = %.9g, step %ld\n", run->restart, ck_t(s),
                ck_step(s));
    la_sim_skip_due(s);
    double now = ck_t(s) + 0.5 * ck_dt(s), k = 0;
    if (s->ck_file && s->ck_every > 0 && s->ck_next <= now)
        s->ck_next = la_next_multiple(s->ck_next, s->ck_every, &k, now);
    else if (s->ck_file && s->ck_next <= now)
        s->ck_next = INFINITY;
    return;
truncated:
    free(buf);
    luaL_error(L, "--restart: '%s' is truncated (its recorders' rows)", run->restart);
}
