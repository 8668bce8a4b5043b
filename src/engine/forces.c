/* The force kinds: one line each. A switch with no default, so -Wswitch
 * names this place when a kind is added to sw_force_kind. */
#include "engine/forces.h"

const swp_force_type *swp_force_type_of(sw_force_kind kind)
{
    switch (kind) {
    case SW_FORCE_GRAVITY: return &swp_gravity;
    case SW_FORCE_DRAG: return &swp_drag;
    case SW_FORCE_SPRINGS: return &swp_springs;
    case SW_FORCE_CENTRAL: return &swp_central;
    case SW_FORCE_MUTUAL: return &swp_mutual;
    }
    return NULL;
}
