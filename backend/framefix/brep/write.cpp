// Writing a model to a BREP or STEP file (the filleted solid of the fillet correction).
#include <filesystem>

#include <BRepTools.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Writer.hxx>

#include "framefix/brep/brep_model.h"
#include "framefix/brep/occt_error.h"
#include "framefix/brep/quiet_occt.h"
#include "framefix/brep/shape.h"

namespace framefix {

void write_shape(const BrepModel& model, const std::string& path) {
    FF_ASSERT(model.shape);
    const std::string ext = std::filesystem::path(path).extension().string();
    occt_call("output", "writing " + path, [&] {
        if (ext == ".brep") {
            if (!BRepTools::Write(model.shape->solid, path.c_str())) throw Error("output", "cannot write " + path);
            return;
        }
        if (ext != ".step" && ext != ".stp") throw Error("output", path + ": write .brep or .step");
        const QuietOcct quiet;
        STEPControl_Writer writer;
        if (writer.Transfer(model.shape->solid, STEPControl_AsIs) != IFSelect_RetDone ||
            writer.Write(path.c_str()) != IFSelect_RetDone)
            throw Error("output", "OpenCASCADE's STEP writer could not write " + path);
    });
}

}  // namespace framefix
