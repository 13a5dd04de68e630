#pragma once
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/impact/outcome.hpp"

namespace aerobreak {

class Simulation;

// The judgement of the fates-fixed rule (docs/IMPACT.md section 4), from the state of the moment:
// every fragment's fate is fixed when it is
//  - held: on an adhesive wall, with less energy (kinetic, in the wall's frame, and stored in its
//    contacts above their rest) than it takes to break its weakest bond or its weakest wall contact
//    (it may still creep along the wall: at its mean velocity along it since `earlier`);
//  - clear: off the wall, its centre of mass moving away, no bond breakable (the same energy, in its
//    own frame, below its weakest bond) and its lowest point unable to come back to the wall;
//  - landing: a primary alone, off an adhesive wall and moving towards it with less kinetic energy
//    along the wall's normal than one adhesion loop with the wall dissipates: it lands and stays,
//    then goes on along the wall at its velocity along it;
//  - bouncing: a primary alone, off a wall without adhesion and moving towards it: it touches it
//    and leaves on a course within bounds; or several primaries off such a wall, not clear of it,
//    with less energy in the wall's frame than their weakest bond's: they stay whole and leave;
// the largest fragment is held or clear, and no two fragments can meet on their paths
// (fragment_paths.hpp). `earlier_positions` are the particles' positions at the time `earlier`
// before now (the last look at the run).
struct FatesJudgement {
  std::string reason;          // empty when every fate is fixed; else the first fragment that is not, and why
  FragmentAnalysis fragments;  // the fragments of the moment, landing and bouncing marked
  // Their velocities: in flight their centre of mass's; held, 0 along the wall's normal (a held
  // fragment's height is bounded: its long-run mean normal velocity vanishes) and the mean since
  // `earlier` along the wall.
  std::vector<Vec3> velocities;
};
FatesJudgement judge_fates(const Simulation& simulation, const std::vector<Vec3>& earlier_positions, double earlier);

// Why a fragment off the wall and moving away may still swing back to it by its rigid rotation
// alone (its shape kept, its internal motion left out); empty if none can. A fragment passes if
// the clear fate's bound with no internal energy clears it, or else, if `follow_rigid_turn`, if
// turning at its rigid rotation (w = I^-1 L) about that fixed axis while its centre rises, its
// lowest point stays off the wall until its bounding sphere has cleared it (a heuristic: a free
// body's axis wanders and its primaries move about it, and a floppy cluster can flex back to the
// wall; docs/IMPACT.md section 4). The outcome-fixed rule asks it of states that are not break-ups.
std::string swing_back_reason(const Simulation& simulation, bool follow_rigid_turn);

}  // namespace aerobreak
