#pragma once
// A contact sheet: pictures shrunk to thumbnails and tiled in rows, each
// labelled underneath with its name (a folder's pictures in one PNG).

#include <string>
#include <vector>

#include "image/image.hpp"

namespace umbra {

struct SheetPicture {
  std::string label;  // printable ASCII as given, any other character as '?'; shortened with "..." when too long for its tile
  Image picture;      // RGB; empty (0 x 0) for a file with none, whose tile says `note`
  std::string note;   // "failed", "timed out": what the empty tile says
};

// `picture` shrunk by the least whole factor that makes it at most
// `max_width` pixels wide, each pixel the mean of those it stands for; RGB,
// a picture with alpha laid on the sheet's ground.
Image thumbnail(const Image& picture, int max_width);

// Thumbnails at most `thumb_width` pixels wide (each picture shrunk by a
// whole factor, averaging the pixels it merges), in `columns` columns (0: as
// many as make the sheet about square), on a light grey ground; a picture
// that is missing is a pale red tile that says its note. Labels too long
// for a tile are shortened, each as it keeps what tells it from the others.
Image contact_sheet(const std::vector<SheetPicture>& pictures, int thumb_width = 200, int columns = 0);

}  // namespace umbra
