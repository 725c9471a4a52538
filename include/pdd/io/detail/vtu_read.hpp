/// \file vtu_read.hpp
/// Implementation of pdd::read_vtu and pdd::read_pvtu: the XML header of pdd's own .vtu pieces
/// (attributes of the Piece and DataArray tags) and the size-checked reading of their appended
/// raw blocks.
#pragma once

#include <pdd/errors.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The error for file `path`: "path: what".
inline error vtu_error(const std::filesystem::path& path, const std::string& what) {
  return error(path.string() + ": " + what);
}

/// The value of attribute `name` in the XML tag text `tag` (between its quotes), if present.
inline std::optional<std::string> xml_attribute(std::string_view tag, std::string_view name) {
  std::string key(1, ' ');
  key.append(name).append("=\"");
  const std::size_t at = tag.find(key);
  if (at == std::string_view::npos) return std::nullopt;
  const std::size_t begin = at + key.size();
  const std::size_t end = tag.find('"', begin);
  if (end == std::string_view::npos) return std::nullopt;
  return std::string(tag.substr(begin, end - begin));
}

/// Undoes xml_escape (&amp; &lt; &gt; &quot; &apos;); nullopt for any other entity.
inline std::optional<std::string> xml_unescape(std::string_view s) {
  static constexpr std::pair<std::string_view, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] != '&') {
      out += s[i++];
      continue;
    }
    bool known = false;
    for (const auto& [text, c] : entities)
      if (s.substr(i, text.size()) == text) {
        out += c;
        i += text.size();
        known = true;
        break;
      }
    if (!known) return std::nullopt;
  }
  return out;
}

/// Every tag `<name ...>` of the XML text, as its text without the angle brackets.
inline std::vector<std::string_view> xml_tags(std::string_view xml, std::string_view name) {
  std::vector<std::string_view> tags;
  std::string open(1, '<');
  open.append(name).append(" ");
  for (std::size_t at = xml.find(open); at != std::string_view::npos; at = xml.find(open, at + 1)) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string_view::npos) break;
    tags.push_back(xml.substr(at + 1, end - at - 1));
  }
  return tags;
}

/// A non-negative decimal attribute; throws naming the file, tag and attribute otherwise.
inline std::uint64_t vtu_count_attribute(const std::filesystem::path& path, std::string_view tag,
                                         std::string_view name) {
  const auto value = xml_attribute(tag, name);
  if (!value || value->empty() || value->size() > 19 ||
      value->find_first_not_of("0123456789") != std::string::npos)
    throw vtu_error(path, "missing or bad attribute " + std::string(name) + " in <" +
                              std::string(tag.substr(0, tag.find(' '))) + ">");
  return std::stoull(*value);
}

/// One DataArray of a pdd .vtu: its name, VTK type, components and appended-data offset.
struct vtu_array {
  std::string name, type;
  std::uint64_t components = 1;
  std::uint64_t offset = 0;
};

/// The parsed XML header of a pdd .vtu piece; `data_start` is the file offset just after the
/// '_' that opens the appended raw data.
struct vtu_read_header_info {
  std::uint64_t points = 0, cells = 0;
  std::vector<vtu_array> arrays;
  std::uint64_t data_start = 0;
  std::uint64_t file_size = 0;

  /// The array called `name`; throws when the header has none.
  const vtu_array& array(const std::filesystem::path& path, const std::string& name) const {
    for (const vtu_array& a : arrays)
      if (a.name == name) return a;
    throw vtu_error(path, "no DataArray named '" + name + "' (not a .vtu written by pdd)");
  }
};

/// Checks the <VTKFile> tag: an UnstructuredGrid in this machine's byte order, UInt64 headers.
inline void check_vtkfile_tag(const std::filesystem::path& path, std::string_view xml,
                              const char* type) {
  const auto tags = xml_tags(xml, "VTKFile");
  if (tags.size() != 1) throw vtu_error(path, "not a VTK XML file (no <VTKFile> tag)");
  if (xml_attribute(tags[0], "type") != type)
    throw vtu_error(path, std::string("not a VTK ") + type + " file");
  const char* order = std::endian::native == std::endian::big ? "BigEndian" : "LittleEndian";
  if (xml_attribute(tags[0], "byte_order") != order)
    throw vtu_error(path, std::string("byte_order is not ") + order + " (this machine's)");
  if (xml_attribute(tags[0], "header_type") != "UInt64")
    throw vtu_error(path, "header_type is not UInt64 (not written by pdd)");
}

/// Reads and parses the XML header of the .vtu at `path`, opened as `in`.
inline vtu_read_header_info read_vtu_header(const std::filesystem::path& path, std::ifstream& in) {
  vtu_read_header_info h;
  in.seekg(0, std::ios::end);
  h.file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  std::string xml(static_cast<std::size_t>(std::min<std::uint64_t>(h.file_size, 1 << 16)), '\0');
  in.read(xml.data(), static_cast<std::streamsize>(xml.size()));
  const std::string marker = "<AppendedData encoding=\"raw\">";
  const std::size_t at = xml.find(marker);
  const std::size_t underscore = at == std::string::npos ? at : xml.find('_', at);
  if (underscore == std::string::npos)
    throw vtu_error(path, "no raw <AppendedData> section (truncated, or not written by pdd)");
  xml.resize(at);
  h.data_start = underscore + 1;
  check_vtkfile_tag(path, xml, "UnstructuredGrid");
  const auto pieces = xml_tags(xml, "Piece");
  if (pieces.size() != 1) throw vtu_error(path, "expected exactly one <Piece>");
  h.points = vtu_count_attribute(path, pieces[0], "NumberOfPoints");
  h.cells = vtu_count_attribute(path, pieces[0], "NumberOfCells");
  if (h.points > h.file_size || h.cells > h.file_size)
    throw vtu_error(path, "NumberOfPoints or NumberOfCells exceeds the file size (truncated?)");
  for (const std::string_view tag : xml_tags(xml, "DataArray")) {
    vtu_array a;
    a.name = xml_attribute(tag, "Name").value_or("");
    a.type = xml_attribute(tag, "type").value_or("");
    if (xml_attribute(tag, "format") != "appended")
      throw vtu_error(path, "DataArray '" + a.name + "' is not in appended format");
    a.offset = vtu_count_attribute(path, tag, "offset");
    if (xml_attribute(tag, "NumberOfComponents"))
      a.components = vtu_count_attribute(path, tag, "NumberOfComponents");
    h.arrays.push_back(std::move(a));
  }
  return h;
}

/// Reads array `name` of `count` values of type T (VTK type `vtk_type`): checks its type,
/// that its block lies inside the file and that the block's UInt64 byte count is count *
/// sizeof(T). Never reads past the end of the file.
template <class T>
std::vector<T> read_vtu_array(const std::filesystem::path& path, std::ifstream& in,
                              const vtu_read_header_info& h, const std::string& name,
                              const char* vtk_type, std::uint64_t count) {
  const vtu_array& a = h.array(path, name);
  if (a.type != vtk_type)
    throw vtu_error(path, "DataArray '" + name + "' has type " + a.type + ", expected " + vtk_type);
  const std::uint64_t at = h.data_start + a.offset;
  if (count > (h.file_size / sizeof(T)) || at > h.file_size || h.file_size - at < 8)
    throw vtu_error(path, "DataArray '" + name + "' lies past the end of the file (truncated?)");
  std::uint64_t bytes = 0;
  in.seekg(static_cast<std::streamoff>(at));
  in.read(reinterpret_cast<char*>(&bytes), sizeof bytes);
  if (bytes != count * sizeof(T))
    throw vtu_error(path, "DataArray '" + name + "' holds " + std::to_string(bytes) +
                              " bytes, expected " + std::to_string(count * sizeof(T)));
  if (h.file_size - at - 8 < bytes)
    throw vtu_error(path,
                    "DataArray '" + name + "' is cut short by the end of the file (truncated)");
  std::vector<T> values(static_cast<std::size_t>(count));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(bytes));
  if (!in) throw vtu_error(path, "cannot read DataArray '" + name + "'");
  return values;
}

} // namespace pdd::detail
