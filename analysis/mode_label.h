#pragma once
// What a mode is: the labels of docs/methods.md ("Mode labels"), given by labelModes (analysis/modes.h).
#include <optional>
#include <string>

namespace motostab::analysis {

/// What a mode is (docs/methods.md, "Mode labels"). Files and people use toString's names.
enum class ModeLabel {
  Neutral,              ///< a zero root of heading or forward motion (a conserved or cyclic quantity)
  Weave,                ///< roll-led oscillation of the whole vehicle (roll, yaw, lateral, steer)
  Wobble,               ///< steer-led oscillation of the front frame
  Capsize,              ///< the slowest real root of roll-led lateral motion
  Castor,               ///< the fastest decaying real root of steer-led lateral motion
  Bounce,               ///< in-plane motion led by the height
  Pitch,                ///< in-plane motion led by the pitch
  RearHop,              ///< in-plane motion led by the rear suspension (the wheel hopping under the frame)
  FrontTyreRelaxation,  ///< the front tyre's lag leads (its relaxation root)
  RearTyreRelaxation,   ///< the rear tyre's lag leads
  SwingarmBending,      ///< a compliance coordinate leads: swingarm, fork or rider
  SwingarmTorsion,
  SwingarmTwist,
  ForkBending,
  ForkTorsion,
  RiderLean,
  Compliance,           ///< another compliance coordinate (e.g. a third-party plugin's)
  Controller,           ///< a controller's state leads
  Longitudinal,         ///< forward speed and wheel spin (drag, longitudinal tyre slip)
  Other,                ///< none of the above
};
constexpr int kNumModeLabels = static_cast<int>(ModeLabel::Other) + 1;

/// The label's name in files ("weave", "front_tyre_relaxation", "swingarm_twist", ...).
const char* toString(ModeLabel label);
/// The label named `name`, if any.
std::optional<ModeLabel> parseModeLabel(const std::string& name);

}  // namespace motostab::analysis
