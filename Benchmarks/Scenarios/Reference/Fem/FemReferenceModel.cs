using System;
using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The float64 finite-element discretisation of a hyperelastic body on a <see cref="FemBoxMesh"/>: quadratic
    /// Lagrange elements (27-node hexahedra or, in 2-D plane strain, 9-node quadrilaterals) with full 3 × 3 (× 3)
    /// Gauss–Legendre quadrature (points ±√(3/5), 0; weights 5/9, 8/9, 5/9), which integrates the linear stiffness
    /// (degree 4 per direction) and the consistent mass exactly on the box's affine elements.
    /// <code>
    ///   F = I + Σ_a u_a ⊗ ∇N_a        f_int,a = ∫ P(F) ∇N_a dV        K_ab,ik = ∫ ∇N_a,J 𝔸_iJkL(F) ∇N_b,L dV
    ///   M_ab = ∫ ρ N_a N_b dV (consistent)        f_ext,a = ∫ ρ g N_a dV (body force)
    /// </code>
    /// In 2-D, F is the 3 × 3 plane-strain gradient (F_zz = 1, no out-of-plane shear) and integrals carry the mesh's
    /// thickness. Degrees of freedom: Dimension per node (u = x − X, m). Dirichlet conditions fix chosen degrees of
    /// freedom at the values held in the displacement vector; matrices (CSR) and solver vectors hold the free
    /// degrees of freedom only, numbered in node order (<see cref="FreeIndex"/>).
    /// Why hexahedra rather than 10-node tetrahedra: the benchmark bodies are boxes, so Q2 hexahedra mesh them with
    /// no splitting, no edge-midpoint bookkeeping and constant Jacobians; like T10 they do not lock in bending, and
    /// the full 3 × 3 × 3 rule integrates their stiffness exactly (see <see cref="CantileverReference"/> for the observed
    /// mesh convergence).
    /// </summary>
    public sealed partial class FemReferenceModel
    {
        /// <summary>The mesh.</summary>
        public readonly FemBoxMesh Mesh;
        /// <summary>The material.</summary>
        public readonly FemMaterial Material;
        /// <summary>Mass density ρ (kg/m³).</summary>
        public readonly double Density;
        /// <summary>Per degree of freedom: its index among the free ones, or −1 if fixed.</summary>
        public readonly int[] FreeIndex;
        /// <summary>Per free degree of freedom: the global degree of freedom.</summary>
        public readonly int[] FreeDofs;
        /// <summary>The sparsity pattern of every matrix on the free degrees of freedom.</summary>
        public readonly FemCsrMatrix Pattern;

        readonly int m_Dim, m_Nen, m_Nq, m_Ned;
        readonly double[] m_N;        // [q·nen + a]
        readonly double[] m_Grad;     // [(q·nen + a)·dim + J], physical gradient
        readonly double[] m_Weight;   // [q], Gauss weight × det J (× thickness in 2-D)
        readonly int[] m_ScatterMap;  // [(e·ned + r)·ned + c] → CSR value index or −1

        /// <param name="mesh">The mesh.</param>
        /// <param name="material">The material law and moduli.</param>
        /// <param name="density">ρ (kg/m³).</param>
        /// <param name="isFixed">Per global degree of freedom (node·Dimension + component): true if prescribed.</param>
        public FemReferenceModel(FemBoxMesh mesh, in FemMaterial material, double density, bool[] isFixed)
        {
            Mesh = mesh;
            Material = material;
            Density = density;
            m_Dim = mesh.Dimension;
            m_Nen = mesh.NodesPerElement;
            m_Ned = m_Nen * m_Dim;
            m_Nq = m_Nen;
            int dofs = mesh.DofCount;
            FreeIndex = new int[dofs];
            int free = 0;
            for (int d = 0; d < dofs; d++)
                FreeIndex[d] = isFixed[d] ? -1 : free++;
            FreeDofs = new int[free];
            for (int d = 0; d < dofs; d++)
                if (FreeIndex[d] >= 0)
                    FreeDofs[FreeIndex[d]] = d;

            // Reference element: 1-D quadratic Lagrange on nodes −1, 0, 1 at the 3 Gauss points.
            double g = Math.Sqrt(0.6);
            double[] xi = { -g, 0, g }, wi = { 5.0 / 9, 8.0 / 9, 5.0 / 9 };
            var n1 = new double[9];
            var d1 = new double[9];
            for (int q = 0; q < 3; q++)
            {
                double s = xi[q];
                n1[q * 3] = 0.5 * s * (s - 1); n1[q * 3 + 1] = 1 - s * s; n1[q * 3 + 2] = 0.5 * s * (s + 1);
                d1[q * 3] = s - 0.5; d1[q * 3 + 1] = -2 * s; d1[q * 3 + 2] = s + 0.5;
            }
            double hx = mesh.ElementSizeX, hy = mesh.ElementSizeY, hz = mesh.ElementSizeZ;
            double[] scale = { 2 / hx, 2 / hy, 2 / hz };
            double detJ = m_Dim == 3 ? hx * hy * hz / 8 : hx * hy / 4 * hz;
            int q3 = m_Dim == 3 ? 3 : 1;
            m_N = new double[m_Nq * m_Nen];
            m_Grad = new double[m_Nq * m_Nen * m_Dim];
            m_Weight = new double[m_Nq];
            int qi = 0;
            for (int qx = 0; qx < 3; qx++)
            for (int qy = 0; qy < 3; qy++)
            for (int qz = 0; qz < q3; qz++, qi++)
            {
                m_Weight[qi] = wi[qx] * wi[qy] * (m_Dim == 3 ? wi[qz] : 1) * detJ;
                int a = 0;
                for (int ax = 0; ax < 3; ax++)
                for (int ay = 0; ay < 3; ay++)
                for (int az = 0; az < q3; az++, a++)
                {
                    double nx = n1[qx * 3 + ax], ny = n1[qy * 3 + ay], nz = m_Dim == 3 ? n1[qz * 3 + az] : 1;
                    double dx = d1[qx * 3 + ax], dy = d1[qy * 3 + ay], dz = m_Dim == 3 ? d1[qz * 3 + az] : 0;
                    m_N[qi * m_Nen + a] = nx * ny * nz;
                    int o = (qi * m_Nen + a) * m_Dim;
                    m_Grad[o] = dx * ny * nz * scale[0];
                    m_Grad[o + 1] = nx * dy * nz * scale[1];
                    if (m_Dim == 3)
                        m_Grad[o + 2] = nx * ny * dz * scale[2];
                }
            }

            // Pattern: free dofs coupled through an element.
            var rows = new List<int>[free];
            var seen = new HashSet<long>();
            for (int r = 0; r < free; r++)
                rows[r] = new List<int>();
            var dofsE = new int[m_Ned];
            for (int e = 0; e < mesh.ElementCount; e++)
            {
                ElementDofs(e, dofsE);
                foreach (int da in dofsE)
                {
                    int r = FreeIndex[da];
                    if (r < 0)
                        continue;
                    foreach (int db in dofsE)
                    {
                        int c = FreeIndex[db];
                        if (c >= 0 && seen.Add((long)r * free + c))
                            rows[r].Add(c);
                    }
                }
            }
            Pattern = new FemCsrMatrix(rows);
            // Per element entry (r, c): its index in the CSR values, or −1 if either degree of freedom is fixed.
            m_ScatterMap = new int[mesh.ElementCount * m_Ned * m_Ned];
            for (int e = 0; e < mesh.ElementCount; e++)
            {
                ElementDofs(e, dofsE);
                for (int r = 0; r < m_Ned; r++)
                {
                    int fr = FreeIndex[dofsE[r]];
                    for (int c = 0; c < m_Ned; c++)
                    {
                        int fc = FreeIndex[dofsE[c]];
                        m_ScatterMap[(e * m_Ned + r) * m_Ned + c] = fr < 0 || fc < 0 ? -1
                            : Array.BinarySearch(Pattern.Columns, Pattern.RowStart[fr], Pattern.RowStart[fr + 1] - Pattern.RowStart[fr], fc);
                    }
                }
            }
        }

        /// <summary>Free degrees of freedom.</summary>
        public int FreeCount => FreeDofs.Length;

        /// <summary>A zero matrix with the model's pattern.</summary>
        public FemCsrMatrix NewMatrix() => new FemCsrMatrix(Pattern);

        void ElementDofs(int e, int[] dofs)
        {
            for (int a = 0; a < m_Nen; a++)
            {
                int node = Mesh.Elements[e * m_Nen + a];
                for (int i = 0; i < m_Dim; i++)
                    dofs[a * m_Dim + i] = node * m_Dim + i;
            }
        }

        /// <summary>
        /// Internal forces f_int = ∫ P ∇N dV (N, on every degree of freedom, fixed ones included: there they are the
        /// reactions) and, when <paramref name="tangent"/> is not null, the tangent stiffness K = ∂f_int/∂u (N/m) on the
        /// free degrees of freedom (overwritten). Returns the stored energy ∫ Ψ dV (J), or NaN where some Gauss point
        /// has an undefined energy (inverted Neo-Hookean); the outputs are then unspecified.
        /// </summary>
        /// <param name="u">Displacements (m), every degree of freedom.</param>
        /// <param name="force">Internal forces (N), every degree of freedom, overwritten.</param>
        /// <param name="tangent">K on the free degrees of freedom, or null.</param>
        public double InternalForce(ReadOnlySpan<double> u, Span<double> force, FemCsrMatrix tangent)
        {
            force.Clear();
            tangent?.Clear();
            int dim = m_Dim, nen = m_Nen, ned = m_Ned;
            var dofs = new int[ned];
            var ue = new double[ned];
            var fe = new double[ned];
            var ke = tangent != null ? new double[ned * ned] : null;
            var h = new double[nen * 3 * 3 * 3];
            Span<double> f = stackalloc double[9];
            Span<double> p = stackalloc double[9];
            Span<double> a = tangent != null ? stackalloc double[81] : Span<double>.Empty;
            double energy = 0;
            for (int e = 0; e < Mesh.ElementCount; e++)
            {
                ElementDofs(e, dofs);
                for (int k = 0; k < ned; k++)
                    ue[k] = u[dofs[k]];
                Array.Clear(fe, 0, ned);
                if (ke != null)
                    Array.Clear(ke, 0, ke.Length);
                for (int q = 0; q < m_Nq; q++)
                {
                    // f holds H = F − I = Σ_n u_n ⊗ ∇N_n (the material takes the displacement gradient).
                    f.Clear();
                    int go = q * nen * dim;
                    for (int n = 0; n < nen; n++)
                    for (int i = 0; i < dim; i++)
                    {
                        double un = ue[n * dim + i];
                        for (int jj = 0; jj < dim; jj++)
                            f[3 * i + jj] += un * m_Grad[go + n * dim + jj];
                    }
                    if (!Material.Evaluate(f, p, a, out double psi, dim))
                        return double.NaN;
                    double w = m_Weight[q];
                    energy += w * psi;
                    AddStressForce(p, go, w, fe);
                    if (ke != null)
                        AddTangent(a, go, w, h, ke);
                }
                for (int k = 0; k < ned; k++)
                    force[dofs[k]] += fe[k];
                if (ke != null)
                    ScatterSymmetric(tangent, e, ke);
            }
            return energy;
        }

        /// <summary>fe_(n i) += w Σ_J P_iJ ∇N_n,J at the Gauss point whose gradients start at <paramref name="go"/> (one quadrature term of ∫ P ∇N dV).</summary>
        void AddStressForce(ReadOnlySpan<double> p, int go, double w, double[] fe)
        {
            int dim = m_Dim;
            for (int n = 0; n < m_Nen; n++)
            for (int i = 0; i < dim; i++)
            {
                double s = 0;
                for (int jj = 0; jj < dim; jj++)
                    s += p[3 * i + jj] * m_Grad[go + n * dim + jj];
                fe[n * dim + i] += w * s;
            }
        }

        /// <summary>
        /// One quadrature term of a tangent ∫ ∇N 𝔸 ∇N dV into the element matrix <paramref name="ke"/>, upper block triangle
        /// m ≥ n only (<see cref="ScatterSymmetric"/> fills the rest by 𝔸's major symmetry): h[n, i, k, L] = w Σ_J ∇N_n,J 𝔸_iJkL,
        /// then ke_(n i)(m k) += Σ_L h[n, i, k, L] ∇N_m,L. <paramref name="h"/> is scratch of 27 per element node.
        /// </summary>
        void AddTangent(ReadOnlySpan<double> a, int go, double w, double[] h, double[] ke)
        {
            int dim = m_Dim, nen = m_Nen, ned = m_Ned;
            for (int n = 0; n < nen; n++)
            for (int i = 0; i < dim; i++)
            for (int k = 0; k < dim; k++)
            for (int l = 0; l < dim; l++)
            {
                double s = 0;
                for (int jj = 0; jj < dim; jj++)
                    s += m_Grad[go + n * dim + jj] * a[9 * (3 * i + jj) + 3 * k + l];
                h[((n * 3 + i) * 3 + k) * 3 + l] = w * s;
            }
            for (int n = 0; n < nen; n++)
            for (int i = 0; i < dim; i++)
            {
                int row = (n * dim + i) * ned;
                for (int m = n; m < nen; m++)
                {
                    int gm = go + m * dim;
                    for (int k = 0; k < dim; k++)
                    {
                        int ho = ((n * 3 + i) * 3 + k) * 3;
                        double s = 0;
                        for (int l = 0; l < dim; l++)
                            s += h[ho + l] * m_Grad[gm + l];
                        ke[row + m * dim + k] += s;
                    }
                }
            }
        }

        /// <summary>Mirrors the upper block triangle of the element matrix of element <paramref name="e"/> below the diagonal, then scatters it.</summary>
        void ScatterSymmetric(FemCsrMatrix m, int e, double[] ke)
        {
            int dim = m_Dim, ned = m_Ned;
            for (int n = 1; n < m_Nen; n++)
            for (int b = 0; b < n; b++)
            for (int i = 0; i < dim; i++)
            for (int k = 0; k < dim; k++)
                ke[(n * dim + i) * ned + b * dim + k] = ke[(b * dim + k) * ned + n * dim + i];
            Scatter(m, e, ke);
        }

        void Scatter(FemCsrMatrix m, int e, double[] ke)
        {
            int count = m_Ned * m_Ned, o = e * count;
            double[] values = m.Values;
            for (int k = 0; k < count; k++)
            {
                int target = m_ScatterMap[o + k];
                if (target >= 0)
                    values[target] += ke[k];
            }
        }

        /// <summary>The consistent mass matrix M = ∫ ρ N_a N_b dV I (kg) on the free degrees of freedom.</summary>
        public FemCsrMatrix MassMatrix()
        {
            FemCsrMatrix m = NewMatrix();
            int dim = m_Dim, nen = m_Nen, ned = m_Ned;
            var me = new double[ned * ned];
            for (int q = 0; q < m_Nq; q++)
            for (int a = 0; a < nen; a++)
            for (int b = 0; b < nen; b++)
            {
                double v = Density * m_Weight[q] * m_N[q * nen + a] * m_N[q * nen + b];
                for (int i = 0; i < dim; i++)
                    me[(a * dim + i) * ned + b * dim + i] += v;
            }
            for (int e = 0; e < Mesh.ElementCount; e++)
                Scatter(m, e, me);
            return m;
        }

        /// <summary>Body force f_ext = ∫ ρ g N_a dV (N) for a uniform acceleration g (m/s², Dimension components), every degree of freedom.</summary>
        public double[] BodyForce(ReadOnlySpan<double> gravity)
        {
            var f = new double[Mesh.DofCount];
            var dofs = new int[m_Ned];
            for (int e = 0; e < Mesh.ElementCount; e++)
            {
                ElementDofs(e, dofs);
                for (int q = 0; q < m_Nq; q++)
                for (int a = 0; a < m_Nen; a++)
                {
                    double v = Density * m_Weight[q] * m_N[q * m_Nen + a];
                    for (int i = 0; i < m_Dim; i++)
                        f[dofs[a * m_Dim + i]] += v * gravity[i];
                }
            }
            return f;
        }

        /// <summary>The free entries of a full vector.</summary>
        public double[] Gather(ReadOnlySpan<double> full)
        {
            var r = new double[FreeCount];
            for (int k = 0; k < r.Length; k++)
                r[k] = full[FreeDofs[k]];
            return r;
        }
    }
}
