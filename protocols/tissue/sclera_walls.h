// The walls around an elastic sclera (docs/methods/elasticity.md): the cavity wall over the sclera
// removed (the fluid touches the tissue), the retina samples there following the nearest sclera
// particle, and, when the sclera is anchored at its outer surface, the rigid backstop behind it,
// the limbus collar and fan with the clamp, the shell's openings closed, the clamp band's face
// walled, and the bony orbit around elastic fat. Each adds its note.
#pragma once

#include "protocols/scenario/scenario.h"
#include "protocols/tissue/tissue_context.h"

namespace protocols {

void replaceWallsOverSclera(Scenario& s, TissueContext& c);

}  // namespace protocols
