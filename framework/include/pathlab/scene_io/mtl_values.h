#pragma once
/// The materials of an .mtl file, built from its lines as PathLab takes them (each as in the
/// file, or as PathLab rewrote it: a lone "Kd 0.5" as grey, a negative colour as 0, an absurd Ni
/// as 1): each value exactly as tinyobjloader 2.0.0rc10's LoadMtl read it from the same lines,
/// so that a scene's materials are bit for bit what they were when tinyobjloader read them.

#include "pathlab/material.h"

#include <string_view>
#include <vector>

namespace pathlab {

class MtlValues {
public:
    /// A 'newmtl': a material of the defaults (black, Ni 1) that the lines after it change.
    void newMaterial();
    /// A line of the current material as PathLab takes it: Kd, Ks, Kt, Tf, Ke and Ni set their
    /// values; map_Kd sets Kd to 0.6 where no Kd line came before it in the file (tinyobjloader's
    /// flag is per file, not per material); other lines change nothing PathLab models. False where
    /// a lone CR in `text` starts a 'newmtl': a material tinyobjloader would have read and PathLab,
    /// which takes a CR within a line for white space, does not.
    bool line(std::string_view text);

    /// One per 'newmtl', in the file's order.
    const std::vector<Material>& materials() const { return materials_; }

private:
    bool oneLine(const char* token);

    std::vector<Material> materials_;
    bool fileHasKd_ = false;
};

} // namespace pathlab
