// A mesh2 section of literal data (`vertex_vectors { 3, <0,0,0>, <1,0,0>,
// <0,1,0> }`) reaches the grammar as one token (RawKind::Mesh2Section, made
// by the scanner): it is most of a big scene's text, and the grammar would
// build a value and reduce a dozen rules for each entry. The scanner makes
// that token only of a section the grammar would read without complaint,
// so a section reads the same either way; this file turns it into the
// mesh's data, with the checks that need the rest of the mesh.
#include "evaluator.h"
#include "huge_pages.h"

namespace lancer::parse {

namespace {

// Where entry `entry` (0-based) of a section token starts: found again in
// the text, since only a section with a bad index asks.
sg::SourceLocation entry_location(const TokenBuffer& buffer, const RawToken& section, std::size_t entry) {
    sg::SourceLocation where = section.location;
    if (where.line < 1 || where.line > buffer.line_count()) return where;
    const std::string& text = buffer.text;
    std::size_t offset = buffer.line_starts()[where.line - 1];
    for (int column = 1; column < where.column && offset < text.size(); ++column) {
        ++offset;  // columns count code points: step over continuation bytes too
        while (offset < text.size() && (static_cast<unsigned char>(text[offset]) & 0xC0) == 0x80) ++offset;
    }
    std::size_t seen = 0;
    for (; offset < buffer.text.size(); ++offset) {
        const char c = buffer.text[offset];
        if (c == '<' && seen++ == entry) return where;
        if (c == '\n') {
            ++where.line;
            where.column = 1;
        } else {
            ++where.column;
        }
    }
    return section.location;
}

}  // namespace

Value Evaluator::mesh2_section_token(const RawToken& raw) {
    const auto buffer = m_buffers.find(raw.location.file.get());
    if (buffer == m_buffers.end()) return Value::number(-1.0);
    m_mesh2_sections.push_back(Mesh2Section{buffer->second, &raw});
    return Value::number(double(m_mesh2_sections.size() - 1));
}

std::function<void(sg::TriangleMesh&)> Evaluator::literal_mesh2_section(const Value& handle,
                                                                        const sg::SourceLocation& at) {
    const double index = handle.v[0];
    if (!(index >= 0.0 && index < double(m_mesh2_sections.size()))) return [](sg::TriangleMesh&) {};
    auto section = std::make_shared<const Mesh2Section>(m_mesh2_sections[static_cast<std::size_t>(index)]);
    const std::string& name = section->raw->text;
    const std::size_t count = section->raw->vector_size;
    if (name == "vertex_vectors" || name == "normal_vectors") {
        const bool normals = name == "normal_vectors";
        return [section, normals, count](sg::TriangleMesh& mesh) {
            auto& out = normals ? mesh.normals : mesh.positions;
            reserve_on_huge_pages(out, out.size() + count);
            visit_mesh2_entries(*section->buffer, *section->raw, [&](const double* c) {
                const sg::Vec3 v(c[0], c[1], c[2]);
                out.push_back(normals && glm::length(v) > 0 ? glm::normalize(v) : v);
            });
        };
    }
    if (name == "uv_vectors") {
        return [section, count](sg::TriangleMesh& mesh) {
            reserve_on_huge_pages(mesh.uvs, mesh.uvs.size() + count);
            visit_mesh2_entries(*section->buffer, *section->raw,
                                [&](const double* c) { mesh.uvs.emplace_back(c[0], c[1]); });
        };
    }
    if (name == "face_indices") add_triangles(static_cast<long>(count), at);
    Evaluator* ev = this;
    return [ev, section, count, at](sg::TriangleMesh& mesh) {
        const std::string& name = section->raw->text;
        auto in_range = [&](double index, std::size_t size, const char* what, std::size_t entry) {
            if (index < double(size)) return true;
            ev->error(entry_location(*section->buffer, *section->raw, entry),
                      mesh2_index_out_of_range(name, static_cast<long long>(index), what, size));
            return false;
        };
        if (name == "face_indices") {
            reserve_on_huge_pages(mesh.faces, mesh.faces.size() + count);
            std::size_t e = 0;
            visit_mesh2_entries(*section->buffer, *section->raw, [&](const double* indices) {
                sg::TriangleMesh::Face face;
                for (int i = 0; i < 3; ++i)
                    face.position[i] =
                        in_range(indices[i], mesh.positions.size(), "vertex_vectors", e) ? int(indices[i]) : 0;
                mesh.faces.push_back(face);
                ++e;
            });
            return;
        }
        const bool normals = name == "normal_indices";
        if (count != mesh.faces.size()) {
            ev->error(at, mesh2_indices_not_per_face(name, count, mesh.faces.size()));
            return;
        }
        const std::size_t size = normals ? mesh.normals.size() : mesh.uvs.size();
        std::size_t e = 0;
        visit_mesh2_entries(*section->buffer, *section->raw, [&](const double* indices) {
            for (int i = 0; i < 3; ++i)
                (normals ? mesh.faces[e].normal : mesh.faces[e].uv)[i] =
                    in_range(indices[i], size, normals ? "normal_vectors" : "uv_vectors", e) ? int(indices[i]) : -1;
            ++e;
        });
    };
}

}  // namespace lancer::parse
