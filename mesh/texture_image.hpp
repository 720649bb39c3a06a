#pragma once
// A material's texture map (OBJ's map_Kd, glTF's baseColorTexture), decoded:
// what the mesh readers make, the scene's materials hold, the renderer uploads
// and the ray-cast reference samples with the GL's own bilinear filter.

#include <cstdint>
#include <string>
#include <vector>

namespace umbra {

struct TextureImage {
  // How a coordinate outside [0, 1] is taken back into it (glTF's wrapS and
  // wrapT; OBJ's maps repeat).
  enum class Wrap { kRepeat, kClampToEdge, kMirroredRepeat };

  std::string name;  // the file, or the glTF image, for messages
  // The file it was decoded from, as an OBJ's material library names it;
  // "" for a map its model holds inside itself (glTF's, 3MF's).
  std::string file;
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // 8 bits a channel, row 0 at v = 0 (the image's top)
  Wrap wrap_u = Wrap::kRepeat, wrap_v = Wrap::kRepeat;
};

}  // namespace umbra
