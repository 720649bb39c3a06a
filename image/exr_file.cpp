#include "image/exr_file.hpp"

#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/ImathBox.h>

namespace umbra {

void write_exr_into(const std::vector<float>& values, int width, int height, const std::vector<std::string>& channels,
                    const PartialFile& into) {
  const size_t count = channels.size();
  if (values.size() != size_t(width) * size_t(height) * count) throw std::logic_error("write_exr_into: values and size disagree");
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    const size_t pixel = count * sizeof(float);
    for (size_t c = 0; c < count; ++c) {
      header.channels().insert(channels[c], Imf::Channel(Imf::FLOAT));
      // OpenEXR writes from a const buffer through a char* slice.
      char* base = reinterpret_cast<char*>(const_cast<float*>(values.data() + c));
      frame.insert(channels[c], Imf::Slice(Imf::FLOAT, base, pixel, pixel * size_t(width)));
    }
    Imf::OutputFile file(into.temporary_path().c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw std::runtime_error(into.path() + ": cannot write the OpenEXR file: " + e.what());
  }
}

ExrPicture read_exr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    ExrPicture picture;
    picture.width = window.max.x - window.min.x + 1, picture.height = window.max.y - window.min.y + 1;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) picture.channels.push_back(c.name());
    const size_t count = picture.channels.size(), pixel = count * sizeof(float);
    picture.values.assign(size_t(picture.width) * size_t(picture.height) * count, 0.0f);
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < count; ++c) {
      // The slice's origin is the data window's (0, 0), which may lie outside it.
      char* base = reinterpret_cast<char*>(picture.values.data() + c) -
                   (ptrdiff_t(window.min.x) + ptrdiff_t(window.min.y) * picture.width) * ptrdiff_t(pixel);
      frame.insert(picture.channels[c], Imf::Slice(Imf::FLOAT, base, pixel, pixel * size_t(picture.width)));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return picture;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot read the OpenEXR file: " + e.what());
  }
}

}  // namespace umbra
