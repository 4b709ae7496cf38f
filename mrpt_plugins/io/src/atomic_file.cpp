#include <rfir/common/atomic_file.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace rfir::common {
void writeViaTempFile(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    try {
        write(tmp);
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write '" + path + "' (rename failed)");
    }
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& fill) {
    writeViaTempFile(path, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        if (!f) throw std::runtime_error("cannot open '" + path + "' for writing");
        fill(f);
        f.flush();
        if (!f) throw std::runtime_error("error while writing '" + path + "'");
    });
}

}  // namespace rfir::common
