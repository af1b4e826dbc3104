#pragma once
// relt's own settings: the ladder's family and levels, the exchanges and where chains live
// (defaults: replica/replica_settings.h).
#include "render/settings.h"
#include "replica/replica_settings.h"

namespace relt {

struct ReltSettings final : SettingsOf<ReltSettings> {
  ReplicaSettings replica;
};

// A relt render's (throws std::logic_error for another integrator's settings).
inline ReplicaSettings& replicaSettings(RenderSettings& s) { return s.own.get<ReltSettings>().replica; }
inline const ReplicaSettings& replicaSettings(const RenderSettings& s) { return s.own.get<ReltSettings>().replica; }
// The same with the chain options every Markov-chain integrator shares filled in (Kelemen sizes,
// large-step probability).
ReplicaSettings effectiveReplicaSettings(const RenderSettings& s);

}  // namespace relt
