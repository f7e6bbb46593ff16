// Loading STEP / IGES / BREP files and BREP strings into a BrepModel holding exactly one solid.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "framefix/brep/occt_error.h"
#include "framefix/brep/quiet_occt.h"
#include "framefix/core/isolation.h"
#include "framefix/brep/shape.h"

namespace framefix {
namespace {

const char* kOneSolid = "export or select exactly one solid";

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum what, TopAbs_ShapeEnum outside) {
    int n = 0;
    for (TopExp_Explorer it(shape, what, outside); it.More(); it.Next()) ++n;
    return n;
}

std::string plural(int n, const std::string& word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// The one solid of `shape`, or a closed shell turned into a solid; anything else is refused.
// `sew_faces`: loose faces (IGES surface export) are sewn and accepted when they close a shell.
TopoDS_Solid single_solid(const TopoDS_Shape& shape, const std::string& source, bool sew_faces) {
    if (shape.IsNull()) throw Error("load", source + " contains no shape; " + kOneSolid);
    const int solids = count(shape, TopAbs_SOLID, TopAbs_SHAPE);
    const int shells = count(shape, TopAbs_SHELL, TopAbs_SOLID);
    const int faces = count(shape, TopAbs_FACE, TopAbs_SHELL);
    const int edges = count(shape, TopAbs_EDGE, TopAbs_FACE);
    if (solids > 1) throw Error("load", source + " contains " + plural(solids, "solid") + "; " + kOneSolid);
    if (solids == 1) {  // loose shells, faces or edges beside it (construction geometry) are ignored
        TopExp_Explorer it(shape, TopAbs_SOLID);
        return TopoDS::Solid(it.Current());
    }
    if (shells == 1 && faces == 0 && edges == 0) {
        TopExp_Explorer it(shape, TopAbs_SHELL);
        const TopoDS_Shell shell = TopoDS::Shell(it.Current());
        if (!BRep_Tool::IsClosed(shell))
            throw Error("load", source + " contains an open shell, not a solid; close the shell or " +
                                    "export the solid it bounds");
        BRepBuilderAPI_MakeSolid make(shell);
        if (!make.IsDone()) throw Error("load", source + " contains a closed shell that is not a solid");
        TopoDS_Solid solid = make.Solid();
        BRepLib::OrientClosedSolid(solid);
        return solid;
    }
    if (shells + faces + edges == 0)
        throw Error("load", source + " contains no solid (no geometry at all); " + kOneSolid);
    if (sew_faces && shells == 0 && faces >= 2) {  // IGES stores a solid as loose trimmed faces
        BRepBuilderAPI_Sewing sewing;
        for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) sewing.Add(it.Current());
        sewing.Perform();
        const TopoDS_Shape sewn = sewing.SewedShape();
        if (count(sewn, TopAbs_SHELL, TopAbs_SOLID) == 1 && count(sewn, TopAbs_FACE, TopAbs_SHELL) == 0)
            return single_solid(sewn, source + " (faces sewn)", false);
        throw Error("load", source + " holds " + plural(faces, "face") + " that do not sew into one closed shell; " +
                                "export the solid as STEP");
    }
    throw Error("load", source + " contains no solid but " + plural(shells, "shell") + ", " +
                            plural(faces, "face") + ", " + plural(edges, "edge") + "; " + kOneSolid);
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

template <class Reader>
TopoDS_Shape read_with(Reader& reader, const std::string& path, const char* format) {
    const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
    if (status != IFSelect_RetDone)
        throw Error("load", path + " is not a readable " + format + " file (truncated or not " + format +
                                "); re-export it from the CAD system");
    if (reader.TransferRoots() == 0)
        throw Error("load", path + " holds no transferable " + format + " shape; re-export it");
    return reader.OneShape();
}

TopoDS_Shape read_file(const std::string& path, const std::string& kind) {
    if (kind == "step") {
        STEPControl_Reader reader;
        return read_with(reader, path, "STEP");
    }
    if (kind == "iges") {
        IGESControl_Reader reader;
        return read_with(reader, path, "IGES");
    }
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder))
        throw Error("load", path + " is not a readable BREP file (truncated or not BREP); re-export it");
    return shape;
}

// The one solid of `shape`, checked by BRepCheck and oriented outward. Damaged geometry can
// crash OCCT here as in the readers, so it runs in the same worker process.
TopoDS_Solid checked_solid(const TopoDS_Shape& shape, const std::string& source, const std::string& kind,
                           double& volume) {
    TopoDS_Solid solid = single_solid(shape, source, kind == "iges");
    BRepCheck_Analyzer check(solid);
    if (!check.IsValid())
        throw Error("load", source + " is not a valid solid (BRepCheck_Analyzer failed); repair it, " +
                                "e.g. with FreeCAD's Part > Check geometry and Refine shape");
    GProp_GProps props;
    BRepGProp::VolumeProperties(solid, props);
    if (props.Mass() < 0) {  // inside out: a closed shell oriented inward
        BRepLib::OrientClosedSolid(solid);
        BRepGProp::VolumeProperties(solid, props);
    }
    if (!(props.Mass() > 0)) throw Error("load", source + " contains a solid of zero volume");
    volume = props.Mass();
    return solid;
}

// The measures of a checked solid that the model keeps.
struct SolidMeasures {
    double volume = 0;
    Eigen::Vector3d lo, hi;  // bounding box
};

// The checked solid of `shape` and its measures.
std::pair<TopoDS_Solid, SolidMeasures> measured_solid(const TopoDS_Shape& shape, const std::string& source,
                                                      const std::string& kind) {
    SolidMeasures m;
    const TopoDS_Solid solid = checked_solid(shape, source, kind, m.volume);
    Bnd_Box box;
    BRepBndLib::Add(solid, box, false);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    m.lo = Eigen::Vector3d(x0, y0, z0);
    m.hi = Eigen::Vector3d(x1, y1, z1);
    return {solid, m};
}

// The model of a checked solid: its sub-shape maps and measures.
BrepModel model_of(const TopoDS_Solid& solid, const SolidMeasures& m, const std::string& path, const std::string& kind) {
    auto data = std::make_shared<BrepModel::Shape>();
    data->solid = solid;
    TopExp::MapShapes(solid, TopAbs_FACE, data->faces);
    TopExp::MapShapes(solid, TopAbs_EDGE, data->edges);
    TopExp::MapShapes(solid, TopAbs_VERTEX, data->vertices);
    BrepModel model;
    model.path = path;
    model.kind = kind;
    model.num_faces = data->faces.Extent();
    model.num_edges = data->edges.Extent();
    model.num_vertices = data->vertices.Extent();
    model.volume = m.volume;
    model.bbox_min = m.lo;
    model.bbox_max = m.hi;
    model.shape = std::move(data);
    return model;
}

// The worker's time budget for reading `bytes` of input: OCCT loops for minutes on some damaged
// files (a count changed to 1e8). Valid parts read at about 0.5 s per MB here (HexMe's largest,
// 180 kB: 0.09 s), so this leaves 40x headroom. FRAMEFIX_LOAD_TIMEOUT_S overrides it (0: none).
constexpr double kLoadBaseSeconds = 10, kLoadSecondsPerMB = 20;

double load_timeout_s(double bytes) {
    if (const char* v = std::getenv("FRAMEFIX_LOAD_TIMEOUT_S")) return std::max(0.0, std::atof(v));
    return kLoadBaseSeconds + kLoadSecondsPerMB * bytes / 1e6;
}


// Reads and checks `read()` in a worker process first (isolation.h): a crash or a hang of OCCT on
// a damaged file becomes an Error there. Only then the same read runs here, on the same memory
// state the worker started from. The solid is not sent back: rebuilt from OCCT's binary or text
// BREP it meshes differently on some parts (HexMe s01o, n06o: state those formats do not keep).
BrepModel load_isolated(const std::string& source, const std::string& path, const std::string& kind, double bytes,
                        const std::function<TopoDS_Shape()>& read) {
    const IsolatedTask task{"load", "OpenCASCADE, reading " + source,
                            "the file is damaged or uses geometry OCCT cannot read; re-export it from the CAD system",
                            load_timeout_s(bytes)};
    const auto read_and_check = [&] {
        const QuietOcct quiet;
        return occt_call("load", source, [&] {
            const auto [solid, m] = measured_solid(read(), source, kind);
            return model_of(solid, m, path, kind);
        });
    };
    if (isolation_enabled()) run_isolated(task, [&] { return (read_and_check(), std::string()); });
    return read_and_check();
}

}  // namespace

BrepModel make_model(const TopoDS_Shape& shape, const std::string& source, const std::string& path,
                     const std::string& kind) {
    return occt_call("load", source, [&] {
        const auto [solid, m] = measured_solid(shape, source, kind);
        return model_of(solid, m, path, kind);
    });
}

BrepModel load_shape(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error("load", path + " does not exist; check the path");
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("load", path + " is not a regular file; give a .step, .brep or .iges file");
    if (std::filesystem::file_size(path, ec) == 0)
        throw Error("load", path + " is empty (0 bytes); re-export the part");
    const std::string ext = lower_extension(path);
    std::string kind;
    if (ext == ".step" || ext == ".stp") kind = "step";
    else if (ext == ".brep" || ext == ".brp") kind = "brep";
    else if (ext == ".iges" || ext == ".igs") kind = "iges";
    else
        throw Error("load", path + " has unknown extension '" + ext +
                                "'; give a .step/.stp, .brep or .iges/.igs file");
    const double bytes = double(std::filesystem::file_size(path, ec));
    return load_isolated(path, path, kind, bytes, [&] { return read_file(path, kind); });
}

BrepModel load_brep_string(const std::string& brep_text) {
    if (brep_text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw Error("load", "BREP string is empty; pass shape.exportBrepToString() of a solid");
    return load_isolated("BREP string", "", "brep", double(brep_text.size()), [&] {
        std::istringstream in(brep_text);
        TopoDS_Shape s;
        BRep_Builder builder;
        BRepTools::Read(s, in, builder);
        if (s.IsNull())
            throw Error("load", "BREP string is not readable BREP (truncated?); pass shape.exportBrepToString()");
        return s;
    });
}

std::string to_brep_string(const BrepModel& model) {
    FF_ASSERT(model.shape);
    return occt_call("load", "writing BREP string", [&] {
        std::ostringstream out;
        BRepTools::Write(model.shape->solid, out);
        return out.str();
    });
}

}  // namespace framefix
