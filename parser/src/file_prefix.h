// The first bytes of a file as a stream buffer, a mebibyte at a time: what
// a second reading of a file sees is no longer than what the first one
// checked, however the file has grown since (internal to the parser).
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <streambuf>
#include <vector>

namespace lancer::parse {

class FilePrefix : public std::streambuf {
  public:
    FilePrefix(const std::filesystem::path& path, std::uintmax_t limit)
        : m_file(path, std::ios::binary), m_left(limit), m_buffer(std::size_t(1) << 20) {}
    bool is_open() const { return m_file.is_open(); }
    // A read failed (not the end of the file).
    bool failed() const { return m_file.bad(); }

  protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (m_left == 0 || !m_file) return traits_type::eof();
        m_file.read(m_buffer.data(), std::streamsize(std::min<std::uintmax_t>(m_buffer.size(), m_left)));
        const std::streamsize got = m_file.gcount();
        if (got <= 0) return traits_type::eof();
        m_left -= std::uintmax_t(got);
        setg(m_buffer.data(), m_buffer.data(), m_buffer.data() + got);
        return traits_type::to_int_type(*gptr());
    }

  private:
    std::ifstream m_file;
    std::uintmax_t m_left;
    std::vector<char> m_buffer;
};

}  // namespace lancer::parse
