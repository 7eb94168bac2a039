using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    public sealed partial class FemReferenceModel
    {
        /// <summary>
        /// Adds the Kelvin–Voigt viscous forces f_v = ∫ P_v(F, Ḟ) ∇N dV (N; <see cref="FemViscosity"/>, Ḟ = Σ_a v_a ⊗ ∇N_a)
        /// to <paramref name="force"/> (every degree of freedom) and, when <paramref name="tangent"/> is not null,
        /// <paramref name="velocityFactor"/> · C(u) to it on the free degrees of freedom, C = ∂f_v/∂v (N·s/m; symmetric).
        /// An implicit integrator whose velocity depends on the unknown displacement as ∂v/∂u = c passes c: the tangent
        /// then holds the velocity part of ∂f_v/∂u; the part through F (of relative size ~ h‖Ḟ‖) is left out.
        /// At rest C = β K₀. Uses the material's small-strain Lamé constants.
        /// </summary>
        /// <param name="u">Displacements (m), every degree of freedom.</param>
        /// <param name="v">Velocities (m/s), every degree of freedom.</param>
        /// <param name="beta">Rayleigh coefficient β (s), ≥ 0.</param>
        /// <param name="force">Forces (N), every degree of freedom, added to.</param>
        /// <param name="tangent">Matrix on the free degrees of freedom, added to; or null.</param>
        /// <param name="velocityFactor">c = ∂v/∂u of the caller's integrator (1/s).</param>
        public void AddViscousForce(ReadOnlySpan<double> u, ReadOnlySpan<double> v, double beta, Span<double> force,
            FemCsrMatrix tangent, double velocityFactor)
        {
            int dim = m_Dim, nen = m_Nen, ned = m_Ned;
            var dofs = new int[ned];
            var ue = new double[ned];
            var ve = new double[ned];
            var fe = new double[ned];
            var ke = tangent != null ? new double[ned * ned] : null;
            var hh = new double[nen * 3 * 3 * 3];
            Span<double> h = stackalloc double[9];
            Span<double> hDot = stackalloc double[9];
            Span<double> p = stackalloc double[9];
            Span<double> a = tangent != null ? stackalloc double[81] : Span<double>.Empty;
            for (int e = 0; e < Mesh.ElementCount; e++)
            {
                ElementDofs(e, dofs);
                for (int k = 0; k < ned; k++)
                {
                    ue[k] = u[dofs[k]];
                    ve[k] = v[dofs[k]];
                }
                Array.Clear(fe, 0, ned);
                if (ke != null)
                    Array.Clear(ke, 0, ke.Length);
                for (int q = 0; q < m_Nq; q++)
                {
                    h.Clear();
                    hDot.Clear();
                    int go = q * nen * dim;
                    for (int n = 0; n < nen; n++)
                    for (int i = 0; i < dim; i++)
                    for (int jj = 0; jj < dim; jj++)
                    {
                        double g = m_Grad[go + n * dim + jj];
                        h[3 * i + jj] += ue[n * dim + i] * g;
                        hDot[3 * i + jj] += ve[n * dim + i] * g;
                    }
                    FemViscosity.Evaluate(h, hDot, beta, Material.Mu, Material.Lambda, p, a, dim);
                    double w = m_Weight[q];
                    AddStressForce(p, go, w, fe);
                    // As for the stiffness, with ∂P/∂Ḟ for 𝔸 and the weight c·w.
                    if (ke != null)
                        AddTangent(a, go, velocityFactor * w, hh, ke);
                }
                for (int k = 0; k < ned; k++)
                    force[dofs[k]] += fe[k];
                if (ke != null)
                    ScatterSymmetric(tangent, e, ke);
            }
        }
    }
}
