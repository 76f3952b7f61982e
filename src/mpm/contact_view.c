/* contact_view.c - what contact did in the last step, read through the
 * public API (mpm_contact.h) so that frames and bindings need not see
 * lm_contact's fields (contact.h, private to the engine). */
#include <string.h>

#include "contact.h"

int lm_sim_contact_info(const lm_sim *sim, lm_contact_info *out)
{
    const lm_contact *c = sim->contact;
    memset(out, 0, sizeof *out);
    if (!c || c->npairs == 0) return -1;
    out->stick = c->nodes_stick;
    out->release = c->nodes_release;
    out->slide = c->nodes_slide;
    out->ke_before = c->ke_before;
    out->ke_after = c->ke_after;
    return 0;
}

const unsigned char *lm_sim_contact_state(const lm_sim *sim)
{
    const lm_contact *c = sim->contact;
    return c && c->npairs > 0 ? c->state : NULL;
}

int lm_sim_contact_fields(const lm_sim *sim)
{
    const lm_contact *c = sim->contact;
    return c && c->npairs > 0 ? c->nf : 0;
}

int lm_sim_contact_field(const lm_sim *sim, int f, const double **m, const double **nx,
                         const double **ny)
{
    const lm_contact_field *cf = &sim->contact->f[f];
    *m = cf->m;
    *nx = cf->nx;
    *ny = cf->ny;
    return cf->body;
}

int lm_sim_contact_friction_body(const lm_sim *sim)
{
    const lm_contact *c = sim->contact;
    if (!c) return -1;
    for (int k = 0; k < c->npairs; k++)
        if (c->pairs[k].law == LM_CONTACT_FRICTION) return c->f[c->pairs[k].a].body;
    return -1;
}
