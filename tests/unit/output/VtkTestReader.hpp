// VtkTestReader.hpp: a small reader for the VTK XML files the particle
// writer makes (.vtp with appended raw data, .pvtp, .pvd), for the tests.
//
// It is deliberately strict and independent of the writer: it tokenises the
// XML part into tags, checks that they nest properly, and reads each
// appended array through its declared offset and its UInt64 byte count,
// checking that the arrays tile the appended block exactly. Values come back
// as raw bytes, so the tests can compare them bit for bit.
#pragma once
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtktest {

struct Tag {
    std::string name;
    std::map<std::string, std::string> attributes;
    bool closing = false;      // </name>
    bool selfClosing = false;  // <name ... />
};

inline std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

// Tags of an XML text (no CDATA, no comments: the writer makes none). Throws
// if the tags do not nest, or if text other than whitespace sits between them.
inline std::vector<Tag> parseTags(const std::string& xml) {
    std::vector<Tag> tags;
    std::vector<std::string> open;
    std::size_t pos = 0;
    auto fail = [&](const std::string& what) {
        throw std::runtime_error("XML: " + what + " at byte " + std::to_string(pos));
    };
    while (true) {
        while (pos < xml.size() && std::isspace(static_cast<unsigned char>(xml[pos]))) ++pos;
        if (pos >= xml.size()) break;
        if (xml[pos] != '<') fail("text outside a tag");
        const std::size_t end = xml.find('>', pos);
        if (end == std::string::npos) fail("unterminated tag");
        std::string body = xml.substr(pos + 1, end - pos - 1);
        pos = end + 1;
        if (!body.empty() && body[0] == '?') continue;  // <?xml ...?>
        Tag t;
        if (!body.empty() && body[0] == '/') {
            t.closing = true;
            body.erase(0, 1);
        }
        if (!body.empty() && body.back() == '/') {
            t.selfClosing = true;
            body.pop_back();
        }
        std::size_t i = 0;
        while (i < body.size() && !std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        t.name = body.substr(0, i);
        // attributes: name="value"
        while (true) {
            while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
            if (i >= body.size()) break;
            const std::size_t eq = body.find('=', i);
            if (eq == std::string::npos || eq + 1 >= body.size() || body[eq + 1] != '"')
                fail("bad attribute in <" + t.name + ">");
            const std::size_t close = body.find('"', eq + 2);
            if (close == std::string::npos) fail("unterminated attribute in <" + t.name + ">");
            const std::string key = body.substr(i, eq - i);
            if (t.attributes.count(key)) fail("attribute " + key + " twice in <" + t.name + ">");
            t.attributes[key] = body.substr(eq + 2, close - eq - 2);
            i = close + 1;
        }
        if (t.closing) {
            if (open.empty() || open.back() != t.name) fail("</" + t.name + "> does not close the open tag");
            open.pop_back();
        } else if (!t.selfClosing) {
            open.push_back(t.name);
        }
        tags.push_back(t);
    }
    if (!open.empty()) fail("<" + open.back() + "> never closed");
    return tags;
}

inline const char* hostByteOrder() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1 ? "LittleEndian" : "BigEndian";
}

// One DataArray of a .vtp: where it sits and its raw values.
struct Array {
    std::string section;  // PointData, Points or Verts
    std::string name, type;
    int components = 0;
    std::string bytes;  // the values, as in the file

    std::size_t valueSize() const { return type == "Int64" || type == "Float64" ? 8 : 0; }
    template <class T>
    T at(std::size_t i) const {
        if (sizeof(T) != valueSize() || (i + 1) * sizeof(T) > bytes.size())
            throw std::runtime_error("array " + name + ": bad access");
        T v;
        std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
        return v;
    }
};

struct Piece {
    std::uint64_t points = 0, verts = 0;
    std::map<std::string, Array> arrays;  // by name; the Points array as "Points"
    std::vector<Tag> tags;                // of the XML part
};

// Reads a .vtp written with appended raw data and UInt64 headers.
inline Piece readPiece(const std::string& path) {
    const std::string file = readAll(path);
    const std::string marker = "<AppendedData encoding=\"raw\">";
    const std::size_t m = file.find(marker);
    if (m == std::string::npos) throw std::runtime_error(path + ": no raw AppendedData");
    const std::size_t underscore = file.find('_', m + marker.size());
    if (underscore == std::string::npos) throw std::runtime_error(path + ": no '_' before the data");
    for (std::size_t i = m + marker.size(); i < underscore; ++i)
        if (!std::isspace(static_cast<unsigned char>(file[i])))
            throw std::runtime_error(path + ": text between <AppendedData> and '_'");
    const std::size_t base = underscore + 1;
    const std::string closing = "</AppendedData>\n</VTKFile>\n";
    const std::size_t closeAt = file.rfind("</AppendedData>");
    if (closeAt == std::string::npos || file.compare(closeAt, std::string::npos, closing) != 0)
        throw std::runtime_error(path + ": does not end with </AppendedData></VTKFile>");

    Piece piece;
    // The XML with the binary block cut out must be well formed.
    piece.tags = parseTags(file.substr(0, underscore) + file.substr(closeAt));
    const Tag& root = piece.tags.at(0);
    if (root.name != "VTKFile" || root.attributes.at("type") != "PolyData" ||
        root.attributes.at("header_type") != "UInt64" || root.attributes.at("byte_order") != hostByteOrder())
        throw std::runtime_error(path + ": unexpected VTKFile attributes");

    std::string section;
    std::size_t expectedOffset = 0;  // arrays must tile the block in order
    for (const Tag& t : piece.tags) {
        if (t.name == "Piece" && !t.closing) {
            piece.points = std::stoull(t.attributes.at("NumberOfPoints"));
            piece.verts = std::stoull(t.attributes.at("NumberOfVerts"));
            for (const char* k : {"NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
                if (t.attributes.at(k) != "0") throw std::runtime_error(path + ": " + k + " != 0");
        }
        if ((t.name == "PointData" || t.name == "Points" || t.name == "Verts") && !t.closing)
            section = t.name;
        if (t.name != "DataArray") continue;
        Array a;
        a.section = section;
        a.type = t.attributes.at("type");
        a.name = t.attributes.count("Name") ? t.attributes.at("Name") : "Points";
        a.components = std::stoi(t.attributes.at("NumberOfComponents"));
        if (t.attributes.at("format") != "appended") throw std::runtime_error(path + ": not appended");
        const std::size_t offset = std::stoull(t.attributes.at("offset"));
        if (offset != expectedOffset)
            throw std::runtime_error(path + ": array " + a.name + " not where expected");
        std::uint64_t count = 0;
        if (base + offset + 8 > closeAt)
            throw std::runtime_error(path + ": array " + a.name + " past the end");
        std::memcpy(&count, file.data() + base + offset, 8);
        if (base + offset + 8 + count > closeAt)
            throw std::runtime_error(path + ": array " + a.name + " longer than the file");
        a.bytes = file.substr(base + offset + 8, count);
        expectedOffset = offset + 8 + count;
        if (piece.arrays.count(a.name)) throw std::runtime_error(path + ": array " + a.name + " twice");
        piece.arrays[a.name] = a;
    }
    // The data block ends with the last array (then only whitespace before </AppendedData>).
    for (std::size_t i = base + expectedOffset; i < closeAt; ++i)
        if (!std::isspace(static_cast<unsigned char>(file[i])))
            throw std::runtime_error(path + ": bytes left after the last array");
    return piece;
}

// Tags with a given name in a small XML file (.pvtp, .pvd), after checking
// the whole file is well formed and its root is <VTKFile type=...>.
inline std::vector<Tag> tagsNamed(const std::string& path, const std::string& rootType,
                                  const std::string& name) {
    const std::vector<Tag> tags = parseTags(readAll(path));
    if (tags.empty() || tags[0].name != "VTKFile" || tags[0].attributes.at("type") != rootType)
        throw std::runtime_error(path + ": root is not <VTKFile type=\"" + rootType + "\">");
    std::vector<Tag> out;
    for (const Tag& t : tags)
        if (t.name == name && !t.closing) out.push_back(t);
    return out;
}

}  // namespace vtktest
