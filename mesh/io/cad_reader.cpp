// CAD exchange files, STEP, IGES and BREP, through Open CASCADE: the shape
// read, tessellated with BRepMesh_IncrementalMesh, and every face's
// triangles taken in the shape's coordinates, turned as the face is
// oriented. Faces of one shell share the points of their common edges, so
// that a shell Open CASCADE tessellates closed is a closed mesh. A STEP
// file's colours (XCAF) are its faces' materials.
//
// Built as a module of its own (umbra-cad.so), which umbra opens when it
// reads such a file (cad_module.cpp): Open CASCADE's libraries take 25 ms
// to load, which every other run would otherwise pay. Its one entry,
// umbra_read_cad, says what went wrong as text, not as an exception
// thrown across the module's edge.

#include <Bnd_Box.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_Triangulation.hxx>
#include <Quantity_Color.hxx>
#include <Standard_Failure.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shape.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/common.hpp>

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

// Every face's triangles, points and polygons added to `soup`, each
// polygon with the material `colours` gives its face (none when empty).
void add_faces(const TopoDS_Shape& shape, const TopTools_DataMapOfShapeInteger& colours, PolygonSoup& soup) {
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
    const Standard_Integer* material = colours.Seek(face);
    for (Standard_Integer t = 1; t <= triangles->NbTriangles(); ++t) {
      Standard_Integer a = 0, b = 0, c = 0;
      triangles->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      for (const Standard_Integer corner : {a, b, c}) soup.corners.push_back(first + uint32_t(corner - 1));
      soup.end_polygon(0);
      if (!colours.IsEmpty()) soup.polygon_materials.push_back(material ? *material : -1);
    }
  }
}

// A STEP file's colours (its styles, through XCAF), face by face: a face
// takes its own colour, or else the nearest one of the shapes that hold it
// (its shell, solid, part or assembly). Each colour is a material of `soup`.
class StepColours {
 public:
  StepColours(const Handle(TDocStd_Document)& document, PolygonSoup& soup)
      : tool_(XCAFDoc_DocumentTool::ColorTool(document->Main())), soup_(soup) {}

  // `shape` and the faces within it, whose colour is `held` unless their own.
  void collect(const TopoDS_Shape& shape, int held, TopTools_DataMapOfShapeInteger& faces) {
    Quantity_Color colour;
    if (tool_->GetColor(shape, XCAFDoc_ColorSurf, colour) || tool_->GetColor(shape, XCAFDoc_ColorGen, colour)) held = material(colour);
    if (shape.ShapeType() == TopAbs_FACE) {
      if (held >= 0) faces.Bind(shape, held);
      return;
    }
    for (TopoDS_Iterator parts(shape); parts.More(); parts.Next()) collect(parts.Value(), held, faces);
  }

 private:
  int material(const Quantity_Color& colour) {
    Standard_Real r = 0, g = 0, b = 0;
    colour.Values(r, g, b, Quantity_TOC_sRGB);  // as 3MF's and glTF's colours are given
    // Open CASCADE keeps colours linear: 1 comes back from sRGB as 0.9999999999999999.
    const glm::dvec3 rgb = glm::round(glm::dvec3(r, g, b) * 1e6) / 1e6;
    for (size_t m = 0; m < soup_.materials.size(); ++m)
      if (soup_.materials[m].diffuse == rgb) return int(m);
    SoupMaterial added;
    char name[16];
    std::snprintf(name, sizeof name, "#%02x%02x%02x", unsigned(std::lround(r * 255)), unsigned(std::lround(g * 255)), unsigned(std::lround(b * 255)));
    added.name = name;
    added.diffuse = rgb;
    soup_.materials.push_back(added);
    return int(soup_.materials.size() - 1);
  }

  Handle(XCAFDoc_ColorTool) tool_;
  PolygonSoup& soup_;
};

PolygonSoup read_shape(std::string_view bytes, const std::string& path, CadFormat format, const CadTessellation& tessellation) {
  quiet();
  PolygonSoup soup;
  soup.path = path;
  TopoDS_Shape shape;
  TopTools_DataMapOfShapeInteger colours;
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
    } else if (format == CadFormat::kStep) {
      // Through XCAF, which keeps the file's colours with its shapes.
      STEPCAFControl_Reader reader;
      reader.SetColorMode(true);
      if (reader.ChangeReader().ReadStream(path.c_str(), in) != IFSelect_RetDone) throw fail("cannot read it");
      Handle(TDocStd_Document) document;
      XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
      if (!reader.Transfer(document)) throw fail("cannot read it: it holds no shape Open CASCADE can make");
      TDF_LabelSequence free;
      XCAFDoc_DocumentTool::ShapeTool(document->Main())->GetFreeShapes(free);
      TopoDS_Compound all;
      BRep_Builder builder;
      builder.MakeCompound(all);
      StepColours step_colours(document, soup);
      for (const TDF_Label& label : free) {
        const TopoDS_Shape part = XCAFDoc_ShapeTool::GetShape(label);
        if (part.IsNull()) continue;
        builder.Add(all, part);
        step_colours.collect(part, -1, colours);
      }
      shape = all;
      XCAFApp_Application::GetApplication()->Close(document);
    } else {
      // IGES is read from its file (Open CASCADE reads it from no stream).
      IGESControl_Reader reader;
      if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw fail("cannot read it");
      reader.TransferRoots();
      shape = reader.OneShape();
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
  soup.format = std::string(name) + ", tessellated by Open CASCADE";
  add_faces(shape, colours, soup);
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
