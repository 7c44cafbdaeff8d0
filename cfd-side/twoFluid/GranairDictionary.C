/*---------------------------------------------------------------------------*\
    granair: GranairDictionary (see GranairDictionary.H)
\*---------------------------------------------------------------------------*/
#include "GranairDictionary.H"

#include <cstdlib>
#include <sstream>

#include "OStringStream.H"
#include "error.H"

namespace Foam
{
namespace granairTwoFluid
{

::granair::Dictionary toGranair(const dictionary& dict, const word& key)
{
    if (!dict.isDict(key))
    {
        FatalIOErrorInFunction(dict)
            << "missing sub-dictionary '" << key << "' in " << dict.name()
            << " (expected " << key << " { type ...; ... })" << exit(FatalIOError);
    }
    OStringStream os;
    dict.subDict(key).write(os, false);
    try
    {
        return ::granair::Dictionary::fromString(os.str(), dict.name() + "." + key);
    }
    catch (const std::exception& e)
    {
        fatalFromGranair(dict, e.what());
    }
}

void fatalFromGranair(const dictionary& dict, const std::string& what)
{
    FatalIOErrorInFunction(dict) << what.c_str() << exit(FatalIOError);
    std::abort();  // not reached: exit(FatalIOError) throws or aborts
}

} // namespace granairTwoFluid
} // namespace Foam
