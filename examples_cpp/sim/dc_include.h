/*
 * <demcontact.h> for the simulator plugins. The header generated at the merge of issue 13 also
 * carries unprefixed selector macros (NONE, HERTZ, LINEAR, ROLLING_EPSD, ...) that collide with the
 * hosts' own names (LAMMPS' NONE enumerators, LIGGGHTS' ROLLING_EPSD model id): undefine them here.
 * Every plugin source includes this instead of <demcontact.h>; the DC_-prefixed names are the API.
 */
#ifndef DEMCONTACT_SIM_DC_INCLUDE_H
#define DEMCONTACT_SIM_DC_INCLUDE_H
#include <demcontact.h>
#undef HISTORY_MAX
#undef TANGENTIAL_NONE
#undef TANGENTIAL_LINEAR
#undef TANGENTIAL_MINDLIN
#undef ROLLING_NONE
#undef ROLLING_CONSTANT
#undef ROLLING_EPSD
#undef TWISTING_NONE
#undef TWISTING_SDS
#undef HERTZ
#undef POWERLAW
#undef LINEAR
#undef VISCOELASTIC
#undef NONE
#undef RESTITUTION
#endif
