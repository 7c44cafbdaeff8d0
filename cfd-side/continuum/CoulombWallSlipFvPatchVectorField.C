/*---------------------------------------------------------------------------*\
    granair: coulombWallSlip (see CoulombWallSlipFvPatchVectorField.H)
\*---------------------------------------------------------------------------*/
#include "CoulombWallSlipFvPatchVectorField.H"

#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

namespace Foam
{
namespace granair
{

void coulombWallSlipFvPatchVectorField::checkCoefficient(const dictionary& dict) const
{
    if (!(frictionCoefficient_ >= 0 && frictionCoefficient_ < GREAT))
    {
        FatalIOErrorInFunction(dict)
            << "patch " << patch().name() << ", field " << internalField().name()
            << ": frictionCoefficient = " << frictionCoefficient_
            << ", expected a wall friction coefficient mu_w = tan(wall friction angle) >= 0"
            << exit(FatalIOError);
    }
}

coulombWallSlipFvPatchVectorField::coulombWallSlipFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    partialSlipFvPatchVectorField(p, iF),
    frictionCoefficient_(0),
    pName_("p"),
    muName_("muMixture")
{
    refValue() = Zero;
}

coulombWallSlipFvPatchVectorField::coulombWallSlipFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    partialSlipFvPatchVectorField(p, iF),
    frictionCoefficient_(dict.get<scalar>("frictionCoefficient")),
    pName_(dict.lookupOrDefault<word>("p", "p")),
    muName_(dict.lookupOrDefault<word>("mu", "muMixture"))
{
    checkCoefficient(dict);
    refValue() = Zero;
    // Start as no-slip (the powder at rest sticks) unless a restart gives f.
    valueFraction() = dict.found("valueFraction") ? scalarField("valueFraction", dict, p.size()) : scalarField(p.size(), 1.0);
    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=((1.0 - valueFraction())*transform(I - sqr(patch().nf()), patchInternalField()));
    }
}

coulombWallSlipFvPatchVectorField::coulombWallSlipFvPatchVectorField
(
    const coulombWallSlipFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    partialSlipFvPatchVectorField(ptf, p, iF, mapper),
    frictionCoefficient_(ptf.frictionCoefficient_),
    pName_(ptf.pName_),
    muName_(ptf.muName_)
{}

coulombWallSlipFvPatchVectorField::coulombWallSlipFvPatchVectorField(const coulombWallSlipFvPatchVectorField& ptf)
:
    partialSlipFvPatchVectorField(ptf),
    frictionCoefficient_(ptf.frictionCoefficient_),
    pName_(ptf.pName_),
    muName_(ptf.muName_)
{}

coulombWallSlipFvPatchVectorField::coulombWallSlipFvPatchVectorField
(
    const coulombWallSlipFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    partialSlipFvPatchVectorField(ptf, iF),
    frictionCoefficient_(ptf.frictionCoefficient_),
    pName_(ptf.pName_),
    muName_(ptf.muName_)
{}

void coulombWallSlipFvPatchVectorField::updateCoeffs()
{
    if (updated()) return;

    // Before the solver has made p and the viscosity (reading 0/U), keep f.
    const objectRegistry& db = this->db();
    if (db.foundObject<volScalarField>(pName_) && db.foundObject<volScalarField>(muName_))
    {
        const scalarField& pw = patch().lookupPatchField<volScalarField, scalar>(pName_);
        const scalarField& muw = patch().lookupPatchField<volScalarField, scalar>(muName_);
        const vectorField nHat(patch().nf());
        const vectorField Uc(patchInternalField());
        const scalarField& delta = patch().deltaCoeffs();
        scalarField& f = valueFraction();
        forAll(f, facei)
        {
            const vector& n = nHat[facei];
            const scalar slip = mag(Uc[facei] - n*(n & Uc[facei]));
            // The stress no-slip would need, against the friction limit.
            const scalar holding = muw[facei]*delta[facei]*slip;
            const scalar limit = frictionCoefficient_*max(pw[facei], scalar(0));
            // No contact (p <= 0): free slip; else stick below the limit, slide at it.
            f[facei] = limit <= 0 ? scalar(0) : holding > limit ? limit/holding : scalar(1);
        }
    }
    partialSlipFvPatchVectorField::updateCoeffs();
}

void coulombWallSlipFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntry("frictionCoefficient", frictionCoefficient_);
    if (pName_ != "p") os.writeEntry("p", pName_);
    if (muName_ != "muMixture") os.writeEntry("mu", muName_);
    valueFraction().writeEntry("valueFraction", os);
    writeEntry("value", os);
}

makePatchTypeField(fvPatchVectorField, coulombWallSlipFvPatchVectorField);

} // namespace granair
} // namespace Foam
