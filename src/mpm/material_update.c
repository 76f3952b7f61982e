/* material_update.c - step 8's one table: each material kind's update of a
 * particle from its rate (lm_rate, step.h), in the plane form and in the
 * axisymmetric form (axisym.c: the same laws with the hoop rate). The
 * phased step (step.c) and the fused step (step_fused.c) both pick from
 * it (lm_update_at), so a new kind or form is one row here. */
#include "step.h"

lm_update_fn *const lm_material_updates[2][LM_LINEAR_FLUID + 1] = {
    {
        [LM_ELASTIC] = lm_elastic_update_at,
        [LM_MEMBRANE] = lm_membrane_update_at,
        [LM_GAS] = lm_gas_update_at,
        [LM_LINEAR_FLUID] = lm_linear_fluid_update_at,
    },
    {
        [LM_ELASTIC] = lm_axisym_elastic_update_at,
        [LM_MEMBRANE] = lm_axisym_membrane_update_at,
        [LM_GAS] = lm_axisym_gas_update_at,
        [LM_LINEAR_FLUID] = lm_axisym_linear_fluid_update_at,
    },
};
