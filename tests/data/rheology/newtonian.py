"""newtonian.py: reference values of the rheology newtonian (THROW-AWAY model;
run by tests/data/make_reference.py): eta = eta0, phi = phi0."""
Q = dict(eta0=12.5, phi0=0.55)


def reference():
    rows = [((p, g), (Q["eta0"], Q["phi0"]), "constant") for p, g in
            [(1000.0, 10.0), (500.0, 1.0), (100.0, 50.0), (2000.0, 0.5), (50.0, 0.01)]]
    return [dict(variant="", header="constant viscosity; p [Pa], gammaDot [1/s] -> eta [Pa s], phi [-]",
                 parameters=list(Q.items()), inputs=["p", "gammaDot"], outputs=["eta", "phi"], rows=rows)]
