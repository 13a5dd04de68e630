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
//    contacts above their rest) than it takes to break its weakest bond or its weakest wall contact;
//  - clear: off the wall, its centre of mass moving away, no bond breakable (the same energy, in its
//    own frame, below its weakest bond) and its lowest point unable to come back to the wall;
//  - landing: a primary alone, off an adhesive wall and moving towards it with less kinetic energy
//    than one adhesion loop with the wall dissipates: it lands and stays;
//  - bouncing: a primary alone, off a wall without adhesion and moving towards it: it touches it
//    and leaves on a course within bounds;
// the largest fragment is held or clear, and no two fragments can meet on their paths
// (fragment_paths.hpp; two held fragments, which the quiet rule leaves out too, excepted).
struct FatesJudgement {
  std::string reason;            // empty when every fate is fixed; else the first fragment that is not, and why
  FragmentAnalysis fragments;    // the fragments of the moment, landing and bouncing marked
  std::vector<Vec3> velocities;  // their centre-of-mass velocities
};
FatesJudgement judge_fates(const Simulation& simulation);

}  // namespace aerobreak
