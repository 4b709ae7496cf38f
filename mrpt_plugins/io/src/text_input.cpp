/* rfir: bounded reading of text inputs. */
#include <rfir/common/text_input.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace rfir::common {
void openTextInput(std::ifstream& f, const std::string& path, const std::string& what) {
    std::error_code ec;
    // An ifstream opens a directory and only fails on the first read, which
    // would be reported as an empty input or a read error.
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error(path + ": is a directory, not a " + what);
    f.open(path, std::ios::binary);
    if (!f) throw std::runtime_error(path + ": cannot open " + what);
}

bool getBoundedLine(std::istream& in, std::string& line, const std::string& name,
                    size_t lineNo, size_t maxBytes) {
    line.clear();
    const std::istream::sentry ok(in, true);
    if (!ok) return false;
    std::streambuf* sb = in.rdbuf();
    for (;;) {
        const int c = sb->sbumpc();
        if (c == std::char_traits<char>::eof()) {
            // As std::getline: a last line without newline is a line; nothing
            // read at all is the end.
            in.setstate(line.empty() ? std::ios::eofbit | std::ios::failbit
                                     : std::ios::eofbit);
            return !line.empty();
        }
        if (c == '\n') return true;
        if (line.size() >= maxBytes)
            throw std::runtime_error(name + ":" + std::to_string(lineNo) +
                                     ": line longer than " + std::to_string(maxBytes) +
                                     " bytes (not a text file?)");
        line.push_back(char(c));
    }
}

std::string readSmallTextFile(const std::string& path, const std::string& what,
                              uint64_t maxBytes) {
    std::ifstream f;
    openTextInput(f, path, what);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw std::runtime_error(path + ": not a regular file (" + what + ")");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes)
        throw std::runtime_error(path + ": " + std::to_string(size) +
                                 " bytes, over the " + std::to_string(maxBytes) +
                                 "-byte limit of a " + what);
    std::string text, line;
    for (size_t n = 1; getBoundedLine(f, line, path, n); n++) {
        text += line;
        if (!f.eof()) text += '\n';
        if (text.size() > maxBytes)  // the file grew while being read
            throw std::runtime_error(path + ": over the " + std::to_string(maxBytes) +
                                     "-byte limit of a " + what);
    }
    if (f.bad()) throw std::runtime_error(path + ": read error");
    return text;
}
}  // namespace rfir::common
