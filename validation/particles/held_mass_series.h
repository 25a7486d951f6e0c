#pragma once
// The mass each object holds over a particle reference's run, frame by
// frame, so a particle reference (LIGGGHTS dumps, Bullet or ODE frames) and
// the height-span model (models/heightspan: held_mass.csv) compare stage by
// stage: filled, lifted, carried, dumped. A grain is held by the rule of
// mass_held_by_object_kg (particle_observables.h): its centre inside the
// object's mesh or in its open-top hull, the object placed at its pose at
// the frame's time (ObjectSpec::pose_at).
//
// held_mass.csv: a header "time_s,<object>_mass_kg,..." (the height-span
// model's file has the same <object>_mass_kg columns beside others), one row
// per frame, values printed round-trip exact.

#include <map>
#include <string>
#include <vector>

#include "models/core/config/scene.h"
#include "validation/particles/grain_set.h"

namespace repose {

// One frame of a run: the grains at a time.
struct GrainFrame {
  double time_s = 0.0;
  GrainSet grains;
};

struct HeldMassSeries {
  std::vector<double> time_s;                       // one per frame, as given
  std::vector<std::string> objects;                 // names, in scene order
  std::vector<std::vector<double>> mass_kg;         // per object, per frame
};

// The held mass of every keyframed object (free bodies are left out: their
// pose is the engine's, not the scene's) in every frame, all grains of
// density density_kg_m3. An object without a name is "object_<k>".
HeldMassSeries held_mass_series(const std::vector<ObjectSpec>& objects, const std::vector<GrainFrame>& frames,
                                double density_kg_m3);

// Writes held_mass.csv (see above); InputError when it cannot.
void write_held_mass_csv(const std::string& path, const HeldMassSeries& series);

// Every "<object>_mass_kg" column of a held_mass.csv (this module's or the
// height-span model's) as (time, mass) samples, by object name. InputError
// naming the file and line for a missing time_s column, a ragged row or a
// value that is not a number.
struct HeldMassTrack {
  std::vector<double> time_s;
  std::vector<double> mass_kg;
};
std::map<std::string, HeldMassTrack> read_held_mass_csv(const std::string& path);

}  // namespace repose
