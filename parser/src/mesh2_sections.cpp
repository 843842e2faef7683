// A mesh2 section that is nothing but literal data (`vertex_vectors { 3,
// <0,0,0>, <1,0,0>, <0,1,0> }`) is read here straight from the raw tokens,
// without the grammar: it is most of a big scene's text, and the grammar
// would build a value and reduce a dozen rules for each entry. Anything
// else in a section (an expression, a macro, a directive, a texture index,
// an entry the grammar would reject) leaves the whole section to the
// grammar, whose mesh2_vectors / mesh2_indices say what is wrong with it;
// so a section reads the same either way.
#include <cmath>
#include <limits>

#include "evaluator.h"

namespace lancer::parse {

namespace {

bool is_punct(const RawToken& token, const char* text) {
    return token.kind == RawKind::Punct && token.text == text;
}

bool whole_index(double x) {
    return x == std::floor(x) && x >= 0.0 && x <= double(std::numeric_limits<int>::max());
}

}  // namespace

bool Evaluator::is_mesh2_section_name(const std::string& word) {
    return word == "vertex_vectors" || word == "normal_vectors" || word == "uv_vectors" || word == "face_indices" ||
           word == "normal_indices" || word == "uv_indices";
}

std::optional<Evaluator::Symbol> Evaluator::read_literal_mesh2_section(const RawToken& keyword) {
    if (!m_pending.empty() || m_frames.empty()) return std::nullopt;
    Frame& frame = *m_frames.back();
    const std::vector<RawToken>& tokens = frame.buffer->tokens;
    std::size_t i = frame.position;
    if (i >= frame.end || !is_punct(tokens[i], "{")) return std::nullopt;
    const std::size_t open = i++;
    if (i >= frame.end || tokens[i].kind != RawKind::Number) return std::nullopt;
    const double declared = tokens[i++].number;
    const bool uv = keyword.text == "uv_vectors";
    const bool indices = keyword.text.find("_indices") != std::string::npos;
    const std::uint32_t size = uv ? 2 : 3;
    // Only a well-formed section is taken: checking first keeps a bad one's
    // errors the grammar's, and reads nothing twice when it is left.
    std::size_t entries = 0;
    std::size_t close = 0;
    for (bool comma_allowed = true; i < frame.end; ++i) {
        const RawToken& token = tokens[i];
        if (is_punct(token, ",") && comma_allowed) {
            comma_allowed = false;
            continue;
        }
        if (is_punct(token, "}")) {
            close = i;
            break;
        }
        if (token.kind != RawKind::Vector || token.vector_size != size) return std::nullopt;
        if (indices) {
            const double* c = frame.buffer->components(token);
            if (!whole_index(c[0]) || !whole_index(c[1]) || !whole_index(c[2])) return std::nullopt;
        }
        ++entries;
        comma_allowed = true;
    }
    if (close == 0 || declared != double(entries)) return std::nullopt;

    Mesh2Section section;
    section.name = keyword.text;
    section.buffer = frame.buffer;
    section.where.reserve(entries);
    for (std::size_t t = open + 2; t < close; ++t)
        if (tokens[t].kind == RawKind::Vector) section.where.push_back(static_cast<std::uint32_t>(t));
    frame.position = close + 1;
    m_mesh2_sections.push_back(std::move(section));
    SourceRange range{tokens[open].location, tokens[close].location};
    return Symbol(Parser::token::TOK_MESH2_SECTION, TokenValue{"{", Value::number(double(m_mesh2_sections.size() - 1))},
                  range);
}

std::function<void(sg::TriangleMesh&)> Evaluator::literal_mesh2_section(const Value& handle,
                                                                        const sg::SourceLocation& at) {
    const auto index = static_cast<std::size_t>(handle.v[0]);
    if (index >= m_mesh2_sections.size()) return [](sg::TriangleMesh&) {};
    auto section = std::make_shared<const Mesh2Section>(std::move(m_mesh2_sections[index]));
    m_mesh2_sections[index] = Mesh2Section{};
    const std::string& name = section->name;
    const std::size_t count = section->where.size();
    if (name == "vertex_vectors" || name == "normal_vectors") {
        const bool normals = name == "normal_vectors";
        return [section, normals, count](sg::TriangleMesh& mesh) {
            auto& out = normals ? mesh.normals : mesh.positions;
            out.reserve(out.size() + count);
            for (std::size_t e = 0; e < count; ++e) {
                const double* c = section->entry(e);
                const sg::Vec3 v(c[0], c[1], c[2]);
                out.push_back(normals && glm::length(v) > 0 ? glm::normalize(v) : v);
            }
        };
    }
    if (name == "uv_vectors") {
        return [section, count](sg::TriangleMesh& mesh) {
            mesh.uvs.reserve(mesh.uvs.size() + count);
            for (std::size_t e = 0; e < count; ++e) mesh.uvs.emplace_back(section->entry(e)[0], section->entry(e)[1]);
        };
    }
    if (name == "face_indices") add_triangles(static_cast<long>(count), at);
    Evaluator* ev = this;
    return [ev, section, count, at](sg::TriangleMesh& mesh) {
        const std::string& name = section->name;
        auto in_range = [&](double index, std::size_t size, const char* what, std::size_t entry) {
            if (index < double(size)) return true;
            const RawToken& token = section->buffer->tokens[section->where[entry]];
            ev->error(token.location, name + " index " + std::to_string(static_cast<long long>(index)) +
                                          " is out of range: " + what + " has " + std::to_string(size) + " entries" +
                                          (size ? " (valid 0.." + std::to_string(size - 1) + ")" : ""));
            return false;
        };
        if (name == "face_indices") {
            mesh.faces.reserve(mesh.faces.size() + count);
            for (std::size_t e = 0; e < count; ++e) {
                sg::TriangleMesh::Face face;
                for (int i = 0; i < 3; ++i) {
                    const double index = section->entry(e)[i];
                    face.position[i] = in_range(index, mesh.positions.size(), "vertex_vectors", e) ? int(index) : 0;
                }
                mesh.faces.push_back(face);
            }
            return;
        }
        const bool normals = name == "normal_indices";
        if (count != mesh.faces.size()) {
            ev->error(at, name + " lists " + std::to_string(count) + " entries but face_indices has " +
                              std::to_string(mesh.faces.size()) + " (it must come after face_indices, one per face)");
            return;
        }
        const std::size_t size = normals ? mesh.normals.size() : mesh.uvs.size();
        for (std::size_t e = 0; e < count; ++e) {
            for (int i = 0; i < 3; ++i) {
                const double index = section->entry(e)[i];
                (normals ? mesh.faces[e].normal : mesh.faces[e].uv)[i] =
                    in_range(index, size, normals ? "normal_vectors" : "uv_vectors", e) ? int(index) : -1;
            }
        }
    };
}

}  // namespace lancer::parse
