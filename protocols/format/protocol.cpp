#include "protocols/format/protocol.h"

#include <stdexcept>

#include <fmt/format.h>

#include "protocols/format/stage_names.h"

namespace protocols {

namespace {

template <class Enum, std::size_t N>
std::string_view nameOf(Enum v, const std::array<std::string_view, N>& names) {
  const auto index = static_cast<std::size_t>(v);
  return index < N ? names[index] : std::string_view("?");
}

}  // namespace

const Located<EffectSetting>& EffectSwitches::get(std::string_view effect) const {
  const std::span<const std::string_view> names = effectSwitchNames();
  for (std::size_t k = 0; k < names.size() && k < settings.size(); ++k)
    if (names[k] == effect) return settings[k];
  throw std::logic_error(fmt::format("no effect switch named '{}'", effect));
}

std::string_view toString(EyeKind v) { return nameOf(v, kEyeKindNames); }
std::string_view toString(EyeSide v) { return nameOf(v, kEyeSideNames); }
std::string_view toString(TissueMode v) { return nameOf(v, kTissueModeNames); }
std::string_view toString(Anchoring v) { return nameOf(v, kAnchoringNames); }
std::string_view toString(PostureName v) {
  return v == PostureName::kCustom ? std::string_view("custom") : nameOf(v, kPostureNames);
}
std::string_view toString(EffectSetting v) {
  constexpr std::array<std::string_view, 3> kNames = {"auto", "on", "off"};
  return nameOf(v, kNames);
}
std::string_view toString(AccuracyPreset v) { return nameOf(v, kAccuracyPresetNames); }
std::string_view toString(SurfaceStressName v) { return nameOf(v, kSurfaceStressNames); }
std::string_view toString(WallModelName v) { return nameOf(v, kWallModelNames); }
std::string_view toString(StartName v) { return nameOf(v, kStartNames); }

std::optional<AccuracyPreset> accuracyPresetFromName(std::string_view name) {
  for (std::size_t k = 0; k < kAccuracyPresetNames.size(); ++k)
    if (kAccuracyPresetNames[k] == name) return static_cast<AccuracyPreset>(k);
  return std::nullopt;
}

}  // namespace protocols
