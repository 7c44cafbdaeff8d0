/*---------------------------------------------------------------------------*\
    granair: RestartPoint (see RestartPoint.H)
\*---------------------------------------------------------------------------*/
#include "coupled/RestartPoint.H"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "output/FormatExact.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace Foam
{
namespace granair
{

namespace
{

using ::granair::formatExact;

std::string exact(double v)
{
    return formatExact(v);
}

std::string whole(std::int64_t v)
{
    return std::to_string(v);
}

// A list of numbers "(a b c ...)" from an entry's tokens.
std::vector<double> numbers(const ::granair::Dictionary& d, const std::string& key)
{
    const std::vector<std::string>& t = d.tokens(key);
    if (t.size() < 2 || t.front() != "(" || t.back() != ")")
    {
        ::granair::fail<::granair::InputError>(d.where(key), ": expected a list '( ... )'");
    }
    std::vector<double> out;
    for (std::size_t k = 1; k + 1 < t.size(); ++k)
    {
        char* end = nullptr;
        out.push_back(std::strtod(t[k].c_str(), &end));
        if (end != t[k].c_str() + t[k].size())
        {
            ::granair::fail<::granair::InputError>(d.where(key), ": '", t[k], "' is not a number");
        }
    }
    return out;
}

std::int64_t integer(const ::granair::Dictionary& d, const std::string& key)
{
    return std::int64_t(d.getInt(key));
}

} // namespace


std::string restartDirectory(const std::string& caseDir, const std::string& timeName)
{
    return caseDir + "/restart/" + timeName;
}


void RestartState::write(const std::string& file) const
{
    const std::string tmp = file + ".tmp";
    {
        std::ofstream os(tmp, std::ios::trunc);
        os  << "// granairFoam restart point: the coupling state at t = " << exact(time)
            << " s (see coupled/RestartPoint.H)\n"
            << "time               " << exact(time) << ";\n"
            << "timeName           \"" << timeName << "\";\n"
            << "demStep            " << whole(demStep) << ";\n"
            << "demTime            " << exact(demTime) << ";\n"
            << "particles          " << whole(particles) << ";\n"
            << "seriesRows         " << seriesRows << ";\n"
            << "floorHitsTotal     " << whole(floorHitsTotal) << ";\n"
            << "minRawVoidFraction " << exact(minRawVoidFraction) << ";\n"
            << "vtk\n{\n    origin " << exact(vtkOrigin) << ";\n    next " << vtkNext << ";\n    times (";
        for (double t : vtkTimes)
        {
            os << ' ' << exact(t);
        }
        os  << " );\n}\n";
        if (discharge)
        {
            const ::granair::dem::DischargeBalance& b = balance;
            os  << "discharge\n{\n"
                << "    inserted " << whole(b.inserted) << "; present " << whole(b.present)
                << "; discharged " << whole(b.discharged) << "; removed " << whole(b.removed)
                << "; lost " << whole(b.lost) << ";\n"
                << "    insertedMass " << exact(b.insertedMass) << "; presentMass " << exact(b.presentMass)
                << "; dischargedMass " << exact(b.dischargedMass) << "; removedMass "
                << exact(b.removedMass) << "; lostMass " << exact(b.lostMass) << ";\n"
                << "    reusedTags " << whole(b.reusedTags) << "; maxTagSeen " << whole(maxTagSeen) << ";\n"
                << "    massFlow (";   // the window's samples: t M t M ...
            for (const auto& s : massFlow)
            {
                os << ' ' << exact(s.first) << ' ' << exact(s.second);
            }
            os  << " );\n}\n";
        }
        if (!os.flush())
        {
            ::granair::fail<::granair::InputError>("cannot write the restart state '", tmp, "'");
        }
    }
    if (std::rename(tmp.c_str(), file.c_str()) != 0)
    {
        ::granair::fail<::granair::InputError>
        (
            "cannot rename '", tmp, "' to '", file, "': ", std::strerror(errno)
        );
    }
}


RestartState RestartState::read(const std::string& file)
{
    const ::granair::Dictionary d = ::granair::Dictionary::fromFile(file);
    RestartState s;
    s.time = d.getDouble("time");
    s.timeName = d.getString("timeName");
    s.demStep = integer(d, "demStep");
    s.demTime = d.getDouble("demTime");
    s.particles = integer(d, "particles");
    s.seriesRows = long(d.getInt("seriesRows"));
    s.floorHitsTotal = integer(d, "floorHitsTotal");
    s.minRawVoidFraction = d.getDouble("minRawVoidFraction");
    const ::granair::Dictionary& v = d.subDict("vtk");
    s.vtkOrigin = v.getDouble("origin");
    s.vtkNext = long(v.getInt("next"));
    s.vtkTimes = numbers(v, "times");
    s.discharge = d.has("discharge");
    if (s.discharge)
    {
        const ::granair::Dictionary& c = d.subDict("discharge");
        ::granair::dem::DischargeBalance& b = s.balance;
        b.inserted = integer(c, "inserted");
        b.present = integer(c, "present");
        b.discharged = integer(c, "discharged");
        b.removed = integer(c, "removed");
        b.lost = integer(c, "lost");
        b.insertedMass = c.getDouble("insertedMass");
        b.presentMass = c.getDouble("presentMass");
        b.dischargedMass = c.getDouble("dischargedMass");
        b.removedMass = c.getDouble("removedMass");
        b.lostMass = c.getDouble("lostMass");
        b.reusedTags = integer(c, "reusedTags");
        s.maxTagSeen = integer(c, "maxTagSeen");
        const std::vector<double> m = numbers(c, "massFlow");
        if (m.size() % 2 != 0)
        {
            ::granair::fail<::granair::InputError>(c.where("massFlow"), ": expected pairs 't M'");
        }
        for (std::size_t k = 0; k + 1 < m.size(); k += 2)
        {
            s.massFlow.emplace_back(m[k], m[k + 1]);
        }
    }
    d.checkKnownKeys();
    return s;
}

} // namespace granair
} // namespace Foam
