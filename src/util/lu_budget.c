/* lu_budget.c - one memory budget for the whole process (issue 31 item 5).
 *
 * A script is untrusted input (docs/security.md): it may keep making
 * simulations or figures, each a small userdata to the Lua collector but
 * tens of MB to a GB of engine or pixel memory. The Lua heap has its own
 * cap (src/lua/l_alloc.c), and on its own that bounds nothing else. So the
 * three allocators that grow with what a script asks for - the Lua state,
 * the engine's particle and grid arrays (src/mpm/arrays.c, the threads'
 * grid copies) and the renderer's canvases (src/render/canvas.c) - all
 * charge this one counter, and a charge past the limit is refused: the
 * allocator returns failure and its caller reports lu_budget_oom().
 *
 * Before refusing an engine or renderer charge, the budget asks the Lua
 * state to collect (lu_budget_set_reclaim): a dropped simulation's arrays
 * are freed only when its userdata is finalized, and the collector cannot
 * know how much memory hides behind one. Lua's own charges never reclaim
 * (no collection from inside Lua's allocator); Lua collects by itself
 * before it reports "not enough memory".
 *
 * Counters are atomic: the engine's worker threads and the main thread may
 * charge at once. The reclaim runs only on the thread that registered it,
 * never inside itself. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>

#include "util.h"

static _Atomic size_t used[LU_MEM_KINDS];
static _Atomic size_t total;
static _Atomic size_t limit = (size_t)LU_BUDGET_DEFAULT_MB << 20;

static void (*reclaim_fn)(void *);
static void *reclaim_ud;
static pthread_t reclaim_owner;
static int in_reclaim;

/* the message of this thread's last refusal; kept until forgotten, so that
 * a caller that tried a few more (smaller) allocations still finds why the
 * first one failed */
static _Thread_local char refusal[192];

static const char *const kind_names[LU_MEM_KINDS] = {"engine", "lua", "render"};

void lu_budget_set_limit(size_t bytes) { atomic_store(&limit, bytes); }
size_t lu_budget_limit(void) { return atomic_load(&limit); }
size_t lu_budget_used(lu_mem_kind k) { return atomic_load(&used[k]); }
size_t lu_budget_total(void) { return atomic_load(&total); }

void lu_budget_set_reclaim(void (*fn)(void *), void *ud)
{
    reclaim_fn = fn;
    reclaim_ud = ud;
    reclaim_owner = pthread_self();
}

void lu_budget_clear_reclaim(void *ud)
{
    if (reclaim_ud == ud) reclaim_fn = NULL, reclaim_ud = NULL;
}

/* Adds bytes to the total unless that passes the limit: compare-and-swap,
 * so two threads cannot both take the last megabyte. */
static int try_add(size_t bytes)
{
    size_t cap = atomic_load(&limit), t = atomic_load(&total);
    do {
        if (bytes > cap || t > cap - bytes) return -1;
    } while (!atomic_compare_exchange_weak(&total, &t, t + bytes));
    return 0;
}

static void note_refusal(lu_mem_kind k, size_t bytes)
{
    size_t mb = 1u << 20;
    snprintf(refusal, sizeof refusal,
             "memory limit %zu MB reached (engine: %zu MB, lua: %zu MB, render: %zu MB; "
             "%s asked for %zu MB more)",
             atomic_load(&limit) / mb, lu_budget_used(LU_MEM_ENGINE) / mb,
             lu_budget_used(LU_MEM_LUA) / mb, lu_budget_used(LU_MEM_RENDER) / mb,
             kind_names[k], (bytes + mb - 1) / mb);
}

int lu_budget_charge(lu_mem_kind k, size_t bytes)
{
    if (bytes == 0) return 0;
    if (try_add(bytes) != 0) {
        if (k == LU_MEM_LUA || !reclaim_fn || in_reclaim ||
            !pthread_equal(pthread_self(), reclaim_owner)) {
            note_refusal(k, bytes);
            return -1;
        }
        in_reclaim = 1;
        reclaim_fn(reclaim_ud);
        in_reclaim = 0;
        if (try_add(bytes) != 0) {
            note_refusal(k, bytes);
            return -1;
        }
    }
    atomic_fetch_add(&used[k], bytes);
    return 0;
}

void lu_budget_release(lu_mem_kind k, size_t bytes)
{
    if (bytes == 0) return;
    atomic_fetch_sub(&used[k], bytes);
    atomic_fetch_sub(&total, bytes);
}

int lu_budget_refused(void) { return refusal[0] != '\0'; }

const char *lu_budget_oom(void) { return refusal[0] ? refusal : "out of memory"; }

void lu_budget_forget_refusal(void) { refusal[0] = '\0'; }
