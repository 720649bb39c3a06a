// CAD exchange files, STEP, IGES and BREP, through Open CASCADE: the shape
// read, tessellated with BRepMesh_IncrementalMesh, and every face's
// triangles taken in the shape's coordinates, turned as the face is
// oriented. Faces of one shell share the points of their common edges, so
// that a shell Open CASCADE tessellates closed is a closed mesh.
//
// Built as a module of its own (umbra-cad.so), which umbra opens when it
// reads such a file (cad_module.cpp): Open CASCADE's libraries take 25 ms
// to load, which every other run would otherwise pay. Its one entry,
// umbra_read_cad, says what went wrong as text, not as an exception
// thrown across the module's edge.

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "mesh/io/cad_module.hpp"

namespace umbra {
namespace {

// Why the file cannot be read, for umbra_read_cad to say.
struct CadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Open CASCADE's messages go to its own printers: none on the terminal.
void quiet() {
  static const bool done = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
    return true;
  }();
  (void)done;
}

// Every face's triangles, points and polygons added to `soup`.
void add_faces(const TopoDS_Shape& shape, PolygonSoup& soup) {
  for (TopExp_Explorer faces(shape, TopAbs_FACE); faces.More(); faces.Next()) {
    const TopoDS_Face& face = TopoDS::Face(faces.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangles = BRep_Tool::Triangulation(face, location);
    if (triangles.IsNull()) continue;
    const gp_Trsf placed = location.Transformation();
    const uint32_t first = uint32_t(soup.points.size());
    for (Standard_Integer i = 1; i <= triangles->NbNodes(); ++i) {
      const gp_Pnt p = triangles->Node(i).Transformed(placed);
      soup.points.push_back({p.X(), p.Y(), p.Z()});
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (Standard_Integer t = 1; t <= triangles->NbTriangles(); ++t) {
      Standard_Integer a = 0, b = 0, c = 0;
      triangles->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      for (const Standard_Integer corner : {a, b, c}) soup.corners.push_back(first + uint32_t(corner - 1));
      soup.end_polygon(0);
    }
  }
}

PolygonSoup read_shape(std::string_view bytes, const std::string& path, CadFormat format, const CadTessellation& tessellation) {
  quiet();
  TopoDS_Shape shape;
  const char* name = cad_format_name(format);
  const auto fail = [&](const std::string& why) { return CadError(std::string("Open CASCADE's ") + name + " reader " + why); };
  try {
    std::istringstream in{std::string(bytes)};
    if (format == CadFormat::kBrep) {
      BRep_Builder builder;
      // A stream that throws once it fails: past a broken file's end its
      // reader loops for a number without end (a BREP found by library_fuzzer).
      in.exceptions(std::ios::failbit | std::ios::badbit);
      try {
        BRepTools::Read(shape, in, builder);
      } catch (const std::ios::failure&) {
        throw fail("cannot read it: it ends before its shapes do, or holds text where a number belongs");
      }
    } else {
      // IGES is read from its file (Open CASCADE reads it from no stream).
      std::unique_ptr<XSControl_Reader> reader;
      IFSelect_ReturnStatus status = IFSelect_RetFail;
      if (format == CadFormat::kStep) {
        auto step = std::make_unique<STEPControl_Reader>();
        status = step->ReadStream(path.c_str(), in);
        reader = std::move(step);
      } else {
        auto iges = std::make_unique<IGESControl_Reader>();
        status = iges->ReadFile(path.c_str());
        reader = std::move(iges);
      }
      if (status != IFSelect_RetDone) throw fail("cannot read it");
      reader->TransferRoots();
      shape = reader->OneShape();
    }
    if (shape.IsNull()) throw fail("finds no shape in it");
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (box.IsVoid()) throw fail("finds no surface in it");
    const double diagonal = std::sqrt(box.SquareExtent());
    if (!std::isfinite(diagonal)) throw fail("finds a shape whose size is not a finite number");
    BRepMesh_IncrementalMesh mesh(shape, tessellation.relative_deflection * diagonal, false, tessellation.angle, true);
  } catch (const Standard_Failure& e) {
    throw fail(std::string("cannot read it: ") + e.GetMessageString());
  }
  PolygonSoup soup;
  soup.path = path;
  soup.format = std::string(name) + ", tessellated by Open CASCADE";
  add_faces(shape, soup);
  return soup;
}

}  // namespace
}  // namespace umbra

extern "C" int umbra_read_cad(const char* bytes, size_t size, const char* path, int format, const umbra::CadTessellation* tessellation,
                              umbra::PolygonSoup* soup,
                              std::string* error) {
  try {
    *soup = umbra::read_shape({bytes, size}, path, umbra::CadFormat(format), *tessellation);
    return 1;
  } catch (const std::exception& e) {
    *error = e.what();
    return 0;
  }
}
