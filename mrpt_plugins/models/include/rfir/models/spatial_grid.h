/* rfir: a uniform hash grid of 2D points, the one lookup behind the
 * simulator's tag carpet, the emitter map and the "passed over" counts. */
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rfir::models {
/** Values of type T bucketed by the square cell (side `cell` m) their point
 * falls in. Queries visit cells column by column (x outer, y inner) and a
 * cell's values in insertion order, so a query's order is fixed by the
 * insertions alone. */
template <class T = size_t>
class TSpatialGrid {
  public:
    explicit TSpatialGrid(double cell = 1.0) : m_cell(cell) {}

    bool empty() const { return m_cells.empty(); }
    /** Drops every value and takes a new cell side. */
    void reset(double cell) {
        m_cell = cell;
        m_cells.clear();
    }
    void insert(double x, double y, T value) {
        m_cells[key(cellOf(x), cellOf(y))].push_back(std::move(value));
    }

    /** Calls f(value) for the values of every cell that meets the square
     * [x - r, x + r] x [y - r, y + r]: a superset of those within r. */
    template <class F>
    void forEachInSquare(double x, double y, double r, F&& f) const {
        visit(cellOf(x - r), cellOf(x + r), cellOf(y - r), cellOf(y + r), f);
    }
    /** Calls f(value) for the values of the 3 x 3 cells around (x, y): all
     * those within one cell side of it. */
    template <class F>
    void forEachAround(double x, double y, F&& f) const {
        const int64_t cx = cellOf(x), cy = cellOf(y);
        visit(cx - 1, cx + 1, cy - 1, cy + 1, f);
    }

  private:
    template <class F>
    void visit(int64_t i0, int64_t i1, int64_t j0, int64_t j1, F& f) const {
        for (int64_t i = i0; i <= i1; i++)
            for (int64_t j = j0; j <= j1; j++) {
                const auto it = m_cells.find(key(i, j));
                if (it == m_cells.end()) continue;
                for (const T& v : it->second) f(v);
            }
    }
    int64_t cellOf(double v) const {
        // Saturated: converting a double beyond int64's range is undefined (a
        // far-off query must not be); keys use 32 bits per axis anyway.
        const double c = std::floor(v / m_cell);
        return int64_t(std::clamp(c, -2147483648.0, 2147483647.0));
    }
    static int64_t key(int64_t i, int64_t j) {
        // Shifted as unsigned: a left shift of a negative value is undefined.
        return int64_t((uint64_t(i) << 32) ^ (uint64_t(j) & 0xffffffffULL));
    }

    double m_cell;
    std::unordered_map<int64_t, std::vector<T>> m_cells;
};
}  // namespace rfir::models
