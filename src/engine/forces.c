/* The force kinds: one line each. A switch with no default, so -Wswitch
 * names this place when a kind is added to sw_force_kind. */
#include "engine/forces.h"

#include "stepwise/base.h"

const swp_force_type *swp_force_type_of(sw_force_kind kind)
{
    switch (kind) {
    case SW_FORCE_GRAVITY: return &swp_gravity;
    case SW_FORCE_DRAG: return &swp_drag;
    case SW_FORCE_SPRINGS: return &swp_springs;
    case SW_FORCE_CENTRAL: return &swp_central;
    case SW_FORCE_MUTUAL: return &swp_mutual;
    case SW_FORCE_TREE: return &swp_tree;
    case SW_FORCE_HEAT: return &swp_heat;
    case SW_FORCE_SPH: return &swp_sph;
    }
    return NULL;
}

int swp_force_prepare(const sw_particles *p, sw_force *fo)
{
    const swp_force_type *type = swp_force_type_of(fo->kind);
    fo->work = type && type->work_new ? type->work_new(p->n) : NULL;
    return !type || !type->work_new || fo->work ? SW_OK : SW_ENOMEM;
}
