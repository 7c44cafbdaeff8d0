// CgSnapshotReader.cpp: see CgSnapshotReader.hpp.
#include "cg/CgSnapshotReader.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/Error.hpp"

namespace granair {

namespace {

// LIGGGHTS 3.8 compute pair/gran/local and wall/gran/local: keywords in the
// order their values are written, and how many values each writes.
struct Keyword {
    const char* name;
    int width;
};
constexpr Keyword localKeywords[] = {
    {"pos", 6},          {"vel", 6},         {"id", 3},          {"force", 3},
    {"force_normal", 3}, {"force_tangential", 3}, {"torque", 3}, {"torque_normal", 3},
    {"torque_tangential", 3}, {"history", -1}, {"contactArea", 1}, {"delta", 1},
    {"heatFlux", 1},     {"contactPoint", 3}, {"ms_id", 2}};

const char* particleDumpLine = "dump ID all custom N FILE id x y z vx vy vz radius mass [omegax omegay omegaz]";

// Minimum image of d across the periodic directions of the domain.
Vec3 minimumImage(Vec3 d, const CgDomain& dom) {
    for (int a = 0; a < 3; ++a)
        if (dom.periodic[a]) {
            const double L = dom.period(a);
            if (L > 0) d[a] -= L * std::round(d[a] / L);
        }
    return d;
}

// Map compute column k (0-based) -> dump column index, from names c_ID[k].
std::vector<int> localColumns(const DumpFrame& f, const CgLocalLayout& lay, const std::string& what,
                              const std::string& layoutText, const char* option) {
    std::vector<int> map(lay.width, -1);
    std::string id;
    for (std::size_t c = 0; c < f.columns.size(); ++c) {
        const std::string& n = f.columns[c];
        const auto open = n.find('['), close = n.rfind(']');
        if (n.rfind("c_", 0) != 0 || open == std::string::npos || close != n.size() - 1 || close < open + 2)
            fail<InputError>(what, " ", f.where(), ": column '", n,
                             "' is not a compute column c_ID[k]; dump the compute's columns with `dump local`");
        const std::string thisId = n.substr(2, open - 2);
        if (id.empty()) id = thisId;
        else if (thisId != id)
            fail<InputError>(what, " ", f.where(), ": columns of two computes ('", id, "' and '", thisId, "')");
        const int k = std::atoi(n.substr(open + 1, close - open - 1).c_str());
        if (k < 1 || k > lay.width)
            fail<InputError>(what, " ", f.where(), ": column '", n, "', but the layout '", layoutText, "' has ",
                             lay.width, " values: give ", option,
                             " with the keywords of the compute (see docs/cg-fields.md)");
        map[k - 1] = int(c);
    }
    auto need = [&](int offset, int count, const char* keyword) {
        for (int k = offset; k < offset + count; ++k)
            if (map[k] < 0)
                fail<InputError>(what, " ", f.where(), ": column c_", id, "[", k + 1, "] (", keyword,
                                 ") missing from the dump local line");
    };
    if (lay.force >= 0) need(lay.force, 3, "force");
    if (lay.pos >= 0) need(lay.pos, 6, "pos");
    if (lay.id >= 0) need(lay.id, 2, "id");
    return map;
}

void requireFinite(double v, const DumpFrame& f, std::size_t row, const char* what, const char* quantity) {
    if (!std::isfinite(v))
        fail<InputError>(what, " ", f.where(), ": row ", row + 1, ": ", quantity, " is ", v,
                         " (expected a finite number)");
}

}  // namespace

CgLocalLayout CgLocalLayout::parse(const std::string& keywords, const std::string& where) {
    std::string text = keywords;
    for (auto& ch : text)
        if (ch == ',') ch = ' ';
    std::istringstream is(text);
    std::set<std::string> given;
    for (std::string w; is >> w;) {
        bool known = false;
        for (const auto& k : localKeywords) known = known || w == k.name;
        if (!known) {
            std::string list;
            for (const auto& k : localKeywords) list += std::string(" ") + k.name;
            fail<InputError>(where, ": unknown compute pair/gran/local keyword '", w, "'. Known:", list);
        }
        if (w == "history")
            fail<InputError>(where, ": 'history' writes a pair-style dependent number of values; "
                                    "leave it out of the compute the CG dumps use");
        given.insert(w);
    }
    CgLocalLayout lay;
    for (const auto& k : localKeywords) {
        if (!given.count(k.name)) continue;
        if (std::string(k.name) == "pos") lay.pos = lay.width;
        if (std::string(k.name) == "id") lay.id = lay.width;
        if (std::string(k.name) == "force") lay.force = lay.width;
        lay.width += k.width;
    }
    if (lay.force < 0) fail<InputError>(where, ": layout '", keywords, "' has no 'force'");
    return lay;
}

CgSnapshotReader::CgSnapshotReader(const CgReadOptions& opt) : opt_(opt) {
    if (opt_.particles.empty()) fail<InputError>("CG: no particle dump given (particles)");
    particles_ = std::make_unique<LiggghtsDumpSeries>(opt_.particles, "particle dump");
    if (!opt_.pairs.empty()) {
        pairLayout_ = CgLocalLayout::parse(opt_.pairLayout, "pair layout (pairLayout)");
        if (pairLayout_.pos < 0 && pairLayout_.id < 0)
            fail<InputError>("pair layout (pairLayout) '", opt_.pairLayout, "': needs 'pos' or 'id'");
        pairs_ = std::make_unique<LiggghtsDumpSeries>(opt_.pairs, "pair dump");
    }
    if (!opt_.walls.empty()) {
        wallLayout_ = CgLocalLayout::parse(opt_.wallLayout, "wall layout (wallLayout)");
        if (wallLayout_.pos < 0)
            fail<InputError>("wall layout (wallLayout) '", opt_.wallLayout,
                             "': needs 'pos' (LIGGGHTS writes the wall contact point only there)");
        walls_ = std::make_unique<LiggghtsDumpSeries>(opt_.walls, "wall dump");
    }
    for (const auto& w : opt_.planeWalls)
        if (w.axis < 0 || w.axis > 2) fail<InputError>("plane wall '", w.fix, "': axis ", w.axis, " (expected x, y or z)");
}

CgSnapshot CgSnapshotReader::read(long step) const {
    CgSnapshot snap;
    snap.step = step;
    snap.time = timeOf(step);
    const DumpFrame pf = particles_->read(step);
    snap.domain = pf.domain;
    const char* pwhat = "particle dump";
    auto col = [&](const char* a, const char* b) {
        int c = pf.column(a);
        if (c < 0 && b) c = pf.column(b);
        return c;
    };
    const int cid = col("id", nullptr), cx = col("x", "xu"), cy = col("y", "yu"), cz = col("z", "zu"),
              cvx = col("vx", nullptr), cvy = col("vy", nullptr), cvz = col("vz", nullptr),
              crad = col("radius", nullptr), cm = col("mass", nullptr);
    {
        std::string missing;
        const std::pair<int, const char*> req[] = {{cid, "id"}, {cx, "x"}, {cy, "y"}, {cz, "z"}, {cvx, "vx"},
                                                   {cvy, "vy"}, {cvz, "vz"}, {crad, "radius"}, {cm, "mass"}};
        for (const auto& r : req)
            if (r.first < 0) missing += std::string(" ") + r.second;
        if (!missing.empty()) {
            std::string have;
            for (const auto& c : pf.columns) have += " " + c;
            fail<InputError>(pwhat, " ", pf.where(), ": column(s)", missing, " missing; it has:", have,
                             ". Write it with `", particleDumpLine, "`");
        }
    }
    const int cwx = pf.column("omegax"), cwy = pf.column("omegay"), cwz = pf.column("omegaz");
    snap.hasSpin = cwx >= 0 && cwy >= 0 && cwz >= 0;
    snap.particles.resize(pf.rows);
    std::unordered_map<long, std::size_t> byId;
    byId.reserve(pf.rows);
    for (std::size_t r = 0; r < pf.rows; ++r) {
        CgParticle& p = snap.particles[r];
        p.id = long(pf.at(r, cid));
        p.x = Vec3(pf.at(r, cx), pf.at(r, cy), pf.at(r, cz));
        p.v = Vec3(pf.at(r, cvx), pf.at(r, cvy), pf.at(r, cvz));
        p.radius = pf.at(r, crad);
        p.mass = pf.at(r, cm);
        if (snap.hasSpin) p.omega = Vec3(pf.at(r, cwx), pf.at(r, cwy), pf.at(r, cwz));
        for (int a = 0; a < 3; ++a) {
            requireFinite(p.x[a], pf, r, pwhat, "a position");
            requireFinite(p.v[a], pf, r, pwhat, "a velocity");
        }
        if (!(p.radius > 0.0) || !std::isfinite(p.radius) || !(p.mass > 0.0) || !std::isfinite(p.mass))
            fail<InputError>(pwhat, " ", pf.where(), ": particle ", p.id, " has radius ", p.radius, " m and mass ",
                             p.mass, " kg (expected both finite and > 0)");
        if (!byId.emplace(p.id, r).second)
            fail<InputError>(pwhat, " ", pf.where(), ": particle id ", p.id, " listed twice");
    }

    for (const auto& w : opt_.planeWalls) {
        int c[3];
        for (int a = 0; a < 3; ++a) {
            const std::string name = "f_force_" + w.fix + "[" + std::to_string(a + 1) + "]";
            c[a] = pf.column(name);
            if (c[a] < 0)
                fail<InputError>(pwhat, " ", pf.where(), ": column '", name, "' missing for the plane wall '", w.fix,
                                 "': give its fix wall/gran `store_force yes` and dump f_force_", w.fix,
                                 "[1] f_force_", w.fix, "[2] f_force_", w.fix, "[3]");
        }
        for (std::size_t r = 0; r < pf.rows; ++r) {
            const Vec3 f(pf.at(r, c[0]), pf.at(r, c[1]), pf.at(r, c[2]));
            for (int a = 0; a < 3; ++a) requireFinite(f[a], pf, r, pwhat, "a plane-wall force");
            if (f.isZero(0.0)) continue;
            CgWallContact wc;
            wc.x = snap.particles[r].x;
            wc.point = wc.x;
            wc.point[w.axis] = w.position;
            wc.force = f;
            snap.walls.push_back(wc);
        }
    }

    if (pairs_) {
        const DumpFrame f = pairs_->read(step);
        const auto map = localColumns(f, pairLayout_, "pair dump", opt_.pairLayout, "--pair-layout");
        std::set<std::pair<long, long>> seen;
        snap.pairs.reserve(f.rows);
        for (std::size_t r = 0; r < f.rows; ++r) {
            CgPairContact c;
            for (int a = 0; a < 3; ++a) c.force[a] = f.at(r, map[pairLayout_.force + a]);
            long i = -1, j = -1;
            if (pairLayout_.id >= 0) {
                i = long(f.at(r, map[pairLayout_.id])), j = long(f.at(r, map[pairLayout_.id + 1]));
                if (!seen.insert({std::min(i, j), std::max(i, j)}).second)
                    fail<InputError>("pair dump ", f.where(), ": the contact of particles ", i, " and ", j,
                                     " is listed twice (each contact must be counted once)");
            }
            if (pairLayout_.pos >= 0) {
                for (int a = 0; a < 3; ++a) {
                    c.xi[a] = f.at(r, map[pairLayout_.pos + a]);
                    c.xj[a] = f.at(r, map[pairLayout_.pos + 3 + a]);
                }
            } else {
                auto pi = byId.find(i), pj = byId.find(j);
                if (pi == byId.end() || pj == byId.end())
                    fail<InputError>("pair dump ", f.where(), ": contact of particles ", i, " and ", j,
                                     ", but particle ", pi == byId.end() ? i : j, " is not in the particle dump");
                c.xi = snap.particles[pi->second].x;
                c.xj = snap.particles[pj->second].x;
            }
            for (int a = 0; a < 3; ++a) {
                requireFinite(c.force[a], f, r, "pair dump", "a force");
                requireFinite(c.xi[a] + c.xj[a], f, r, "pair dump", "a position");
            }
            c.xj = c.xi + minimumImage(c.xj - c.xi, snap.domain);
            snap.pairs.push_back(c);
        }
    }

    if (walls_) {
        const DumpFrame f = walls_->read(step);
        const auto map = localColumns(f, wallLayout_, "wall dump", opt_.wallLayout, "--wall-layout");
        for (std::size_t r = 0; r < f.rows; ++r) {
            CgWallContact w;
            for (int a = 0; a < 3; ++a) {
                w.point[a] = f.at(r, map[wallLayout_.pos + a]);
                w.x[a] = f.at(r, map[wallLayout_.pos + 3 + a]);
                w.force[a] = f.at(r, map[wallLayout_.force + a]);
                requireFinite(w.force[a], f, r, "wall dump", "a force");
                requireFinite(w.point[a] + w.x[a], f, r, "wall dump", "a position");
            }
            w.point = w.x + minimumImage(w.point - w.x, snap.domain);
            snap.walls.push_back(w);
        }
    }
    return snap;
}

}  // namespace granair
