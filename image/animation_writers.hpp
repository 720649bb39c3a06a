#pragma once
// The animation writers behind open_animation (animation_file.hpp), one a
// file, each built only where its library is found.

#include <memory>
#include <string>

#include "image/animation_file.hpp"

namespace umbra {

std::unique_ptr<AnimationWriter> open_mp4(const std::string& path, const std::string& shown, const AnimationSettings& settings);
std::unique_ptr<AnimationWriter> open_animated_webp(const std::string& path, const std::string& shown, const AnimationSettings& settings);
std::unique_ptr<AnimationWriter> open_gif(const std::string& path, const std::string& shown, const AnimationSettings& settings);

}  // namespace umbra
