#pragma once
/// Embree's XML scene format, which PathLab does not read: recognised by name or by its first
/// bytes, so that -i refuses it in one line rather than as a malformed OBJ.

#include <string>

namespace pathlab {

/// Whether `path` names an Embree XML scene: its name ends in .xml, or the file starts (after
/// white space and a byte-order mark) with "<?xml" or "<scene". A file that cannot be read is
/// not one: the OBJ reader reports that.
bool isXmlScene(const std::string& path);

/// Throws InputError "FILE: an Embree XML scene; PathLab reads OBJ ..." if isXmlScene(path).
void refuseXmlScene(const std::string& path);

} // namespace pathlab
