// POV-Ray's text object: a TrueType font read with FreeType, the string's
// glyph outlines laid out as POV-Ray 3.7 lays them (TrueType::ProcessNewTTF:
// the first glyph's left edge at the origin, each next one at the previous
// advance plus the kerning pair's value, `offset` added after each), in
// units of the font's em.
#include <cmath>
#include <filesystem>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "evaluator.h"

namespace lancer::parse {

namespace {

// The string's code points: UTF-8 where it decodes, else its bytes.
std::vector<unsigned> code_points(const std::string& text) {
    std::vector<unsigned> out;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        int length = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        bool valid = length > 0 && i + std::size_t(length) <= text.size();
        unsigned code = length == 1 ? c : length == 2 ? c & 0x1F : length == 3 ? c & 0x0F : c & 0x07;
        for (int k = 1; valid && k < length; ++k) {
            const unsigned char next = static_cast<unsigned char>(text[i + std::size_t(k)]);
            valid = (next >> 6) == 2;
            code = code << 6 | (next & 0x3F);
        }
        if (!valid) {
            out.push_back(c);
            ++i;
            continue;
        }
        out.push_back(code);
        i += std::size_t(length);
    }
    return out;
}

// Collects an outline's contours as segments, in font units moved by `at`.
struct OutlineSink {
    std::vector<sg::Text::Segment>* segments;
    sg::Vec2 at, current;
    double unit;
    sg::Vec2 point(const FT_Vector* v) const { return at + unit * sg::Vec2(double(v->x), double(v->y)); }
};

int move_to(const FT_Vector* to, void* user) {
    auto* sink = static_cast<OutlineSink*>(user);
    sink->current = sink->point(to);
    return 0;
}

int line_to(const FT_Vector* to, void* user) {
    auto* sink = static_cast<OutlineSink*>(user);
    sg::Text::Segment segment;
    segment.p[0] = sink->current;
    segment.p[3] = sink->point(to);
    segment.p[1] = segment.p[0];
    segment.p[2] = segment.p[3];
    segment.line = true;
    if (segment.p[0] != segment.p[3]) sink->segments->push_back(segment);
    sink->current = segment.p[3];
    return 0;
}

int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* sink = static_cast<OutlineSink*>(user);
    // A quadratic Bezier, raised to the cubic with the same curve.
    const sg::Vec2 p0 = sink->current, c = sink->point(control), p3 = sink->point(to);
    sg::Text::Segment segment;
    segment.p[0] = p0;
    segment.p[1] = p0 + (2.0 / 3.0) * (c - p0);
    segment.p[2] = p3 + (2.0 / 3.0) * (c - p3);
    segment.p[3] = p3;
    sink->segments->push_back(segment);
    sink->current = p3;
    return 0;
}

int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* sink = static_cast<OutlineSink*>(user);
    sg::Text::Segment segment;
    segment.p[0] = sink->current;
    segment.p[1] = sink->point(c1);
    segment.p[2] = sink->point(c2);
    segment.p[3] = sink->point(to);
    sink->segments->push_back(segment);
    sink->current = segment.p[3];
    return 0;
}

struct Library {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~Library() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

}  // namespace

namespace {

// A character's glyph as POV-Ray 3.7 looks it up: in the font's Unicode
// cmap, then its Macintosh Roman one, then its Microsoft Symbol one
// (povlogo.ttf has only the last two: its logo is the "A" of the Roman
// one).
FT_UInt glyph_for(FT_Face face, unsigned code) {
    static constexpr std::pair<FT_UShort, FT_UShort> kPreference[] = {{0, 3}, {3, 1}, {1, 0}, {3, 0}};
    for (const auto& [platform, encoding] : kPreference) {
        for (FT_Int i = 0; i < face->num_charmaps; ++i) {
            FT_CharMap charmap = face->charmaps[i];
            if (charmap->platform_id != platform || charmap->encoding_id != encoding) continue;
            if (platform == 1 && code > 255) continue;  // a Roman table holds 256 codes
            if (FT_Set_Charmap(face, charmap) != 0) continue;
            if (const FT_UInt glyph = FT_Get_Char_Index(face, code)) return glyph;
        }
    }
    // Beyond what POV-Ray 3.7 reads: a font whose only Unicode table is a
    // full (UCS-4) one.
    if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) == 0) return FT_Get_Char_Index(face, code);
    return 0;
}

}  // namespace

Value Evaluator::internal_font(const Value& number, const SourceRange& where) {
    switch (to_int(number, where)) {
    case 1: return Value::string("timrom.ttf");
    case 2: return Value::string("cyrvetic.ttf");
    case 3: return Value::string("crystal.ttf");
    default: return Value::string("povlogo.ttf");
    }
}

ShapePtr Evaluator::make_text(const Value& font, const SourceRange& wf, const Value& string, const SourceRange& ws,
                              const Value& thickness, const SourceRange& wt, const Value& offset, const SourceRange& wo,
                              const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Text;
    shape->object.location = at;
    sg::Text text;
    text.thickness = to_float(thickness, wt, "a float thickness");
    if (!check_renderable(&text.thickness, 1, wt, "the text thickness")) text.thickness = 1.0;
    // POV's Parse_Vector: a float stands for <f, f, f>.
    const sg::Vec3 spacing = offset.kind == Value::Kind::Float ? sg::Vec3(offset.v[0]) : to_vec3(offset, wo);
    const std::string name = to_string(font, wf);
    const std::string characters = to_string(string, ws);
    shape->object.shape = text;
    if (name.empty()) return shape;

    // Beside the file naming it, then the include path (POV-Ray's fonts are
    // in its include folder), then where Debian's fonts-povray puts them.
    std::vector<std::string> folders = search_folders(wf.begin);
    folders.push_back("/usr/share/fonts/truetype/povray");
    std::string found;
    // POV-Ray adds ".ttf" to a font name without an extension.
    const std::string file = std::filesystem::path(name).has_extension() ? name : name + ".ttf";
    const FileSearch search = find_file(file, folders, wf.begin, "font file", found);
    if (search == FileSearch::Refused) return shape;
    if (search == FileSearch::Missing) {
        error(wf.begin, "cannot find font file \"" + file + "\"");
        return shape;
    }
    std::string bytes;
    if (!read_file(found, wf.begin, "font file", bytes)) return shape;
    text.font = found;

    Library ft;
    if (FT_Init_FreeType(&ft.library) != 0) {
        error(wf.begin, "cannot start FreeType to read the font");
        return shape;
    }
    if (FT_New_Memory_Face(ft.library, reinterpret_cast<const FT_Byte*>(bytes.data()), FT_Long(bytes.size()), 0,
                           &ft.face) != 0 ||
        !FT_IS_SCALABLE(ft.face) || ft.face->units_per_EM == 0) {
        error(wf.begin, "font file \"" + name + "\" is not a TrueType or OpenType font FreeType can read");
        return shape;
    }
    const double unit = 1.0 / double(ft.face->units_per_EM);
    FT_Outline_Funcs funcs{};
    funcs.move_to = move_to;
    funcs.line_to = line_to;
    funcs.conic_to = conic_to;
    funcs.cubic_to = cubic_to;
    sg::Vec2 total(0.0);
    FT_UInt previous = 0;
    bool first = true;
    constexpr std::size_t kMaxCharacters = 100000;
    const std::vector<unsigned> codes = code_points(characters);
    if (codes.size() > kMaxCharacters) {
        error(ws.begin, "text of " + std::to_string(codes.size()) + " characters is more than lancer's limit of " +
                            std::to_string(kMaxCharacters));
        return shape;
    }
    for (unsigned code : codes) {
        // A character the font lacks is drawn as its glyph 0, the font's
        // "missing character" shape, as POV-Ray draws it (povlogo.ttf's is
        // the POV-Ray logo).
        const FT_UInt glyph = glyph_for(ft.face, code);
        if (glyph == 0)
            warning(ws.begin, "the font has no glyph for character " + std::to_string(code) +
                                  "; its missing-character glyph stands in, as in POV-Ray");
        if (FT_Load_Glyph(ft.face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
            ft.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
            warning(ws.begin, "the font has no outline for character " + std::to_string(code) + "; it is skipped");
            continue;
        }
        FT_BBox box;
        FT_Outline_Get_CBox(&ft.face->glyph->outline, &box);
        const double advance = double(ft.face->glyph->metrics.horiAdvance);
        const double bearing = double(ft.face->glyph->metrics.horiBearingX);
        sg::Vec2 place;
        if (first) {
            place = sg::Vec2(-double(box.xMin) * unit, 0.0);
            total.x = (advance - bearing) * unit;
        } else {
            FT_Vector kern{0, 0};
            if (FT_HAS_KERNING(ft.face)) FT_Get_Kerning(ft.face, previous, glyph, FT_KERNING_UNSCALED, &kern);
            place = sg::Vec2(total.x + (bearing - double(box.xMin) + double(kern.x)) * unit, total.y);
            total.x += (advance + double(kern.x)) * unit;
        }
        OutlineSink sink{&text.segments, place, place, unit};
        if (FT_Outline_Decompose(&ft.face->glyph->outline, &funcs, &sink) != 0) {
            error(ws.begin, "font file \"" + name + "\" has a damaged outline for character " + std::to_string(code));
            return shape;
        }
        total += sg::Vec2(spacing.x, spacing.y);
        previous = glyph;
        first = false;
    }
    if (text.segments.empty()) {
        // POV-Ray renders such a text as nothing; so does lancer: an empty
        // union, which any CSG or object { } may still hold.
        warning(at, "text has no visible glyph (an empty string, only spaces, or none the font has)");
        shape->object.kind = sg::Object::Kind::Union;
        shape->object.shape = sg::Group{};
        return shape;
    }
    shape->object.shape = std::move(text);
    return shape;
}

}  // namespace lancer::parse
