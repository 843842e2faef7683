// Tables keyed by a scene's names (its variables, macros and macro
// parameters). An identifier in a loop is looked up in every scope, two
// tables each: hashing its text once and handing the hash to each lookup
// (HashedName) saves the rest; the tables are unordered because a scene
// that includes colors.inc and textures.inc has hundreds of globals.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace lancer::parse {

struct HashedName {
    explicit HashedName(std::string_view name) : text(name), hash(std::hash<std::string_view>{}(name)) {}
    std::string_view text;
    std::size_t hash;
};

struct NameHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view name) const { return std::hash<std::string_view>{}(name); }
    std::size_t operator()(const std::string& name) const { return std::hash<std::string_view>{}(name); }
    std::size_t operator()(const HashedName& name) const { return name.hash; }
};

struct NameEqual {
    using is_transparent = void;
    bool operator()(std::string_view a, std::string_view b) const { return a == b; }
    bool operator()(const HashedName& a, std::string_view b) const { return a.text == b; }
    bool operator()(std::string_view a, const HashedName& b) const { return a == b.text; }
};

template <class T>
using NameMap = std::unordered_map<std::string, T, NameHash, NameEqual>;

}  // namespace lancer::parse
