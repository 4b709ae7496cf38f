#include <rfir/common/atomic_file.h>
#include <rfir/common/text_input.h>
#include <rfir/common/trajectory_io.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rfir::common {
double wrapToPi(double a) {
    a = std::remainder(a, 2 * M_PI);  // [-pi, pi]
    return a <= -M_PI ? a + 2 * M_PI : a;
}

mrpt::poses::CPose2D interpolatePose2D(const mrpt::poses::CPose2D& a,
                                       const mrpt::poses::CPose2D& b, double s) {
    const double phi = a.phi() + s * wrapToPi(b.phi() - a.phi());
    return {a.x() + s * (b.x() - a.x()), a.y() + s * (b.y() - a.y()), wrapToPi(phi)};
}

void saveTUM(const std::string& path, const TPath2D& traj) {
    writeFileAtomically(path, [&](std::ostream& o) {
        o << "# t x y z qx qy qz qw\n" << std::fixed;
        for (const auto& p : traj) {
            const double h = 0.5 * p.pose.phi();
            o << std::setprecision(6) << p.t << " " << std::setprecision(6) << p.pose.x()
              << " " << p.pose.y() << " 0 0 0 " << std::setprecision(9) << std::sin(h)
              << " " << std::cos(h) << "\n";
        }
    });
}

TPath2D loadTUM(const std::string& path) {
    std::ifstream f;
    openTextInput(f, path, "TUM trajectory file");
    return loadTUM(f, path);
}

TPath2D loadTUM(std::istream& f, const std::string& path) {
    TPath2D out;
    std::string line;
    for (int ln = 1; getBoundedLine(f, line, path, size_t(ln)); ln++) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream s(line);
        double v[8];
        int n = 0;
        std::string tok;
        bool bad = false;
        while (s >> tok) {
            if (n >= 8) {
                bad = true;
                break;
            }
            char* end = nullptr;
            v[n] = std::strtod(tok.c_str(), &end);
            if (*end || !std::isfinite(v[n])) {
                bad = true;
                break;
            }
            n++;
        }
        if (n == 0 && !bad) continue;
        if (bad || n != 8)
            throw std::runtime_error(path + ":" + std::to_string(ln) +
                                     ": expected 8 finite numbers 't x y z qx qy qz qw'");
        const double yaw = 2 * std::atan2(v[6], v[7]);
        out.push_back({v[0], mrpt::poses::CPose2D(v[1], v[2], yaw)});
    }
    if (f.bad()) throw std::runtime_error(path + ": read error");
    return out;
}

}  // namespace rfir::common
