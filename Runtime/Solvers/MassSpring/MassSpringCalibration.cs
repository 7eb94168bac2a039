using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// From a physical material (<see cref="ElasticMaterial"/>: E, ν, ρ, ζ) to spring stiffness, damping and masses, in
    /// the spirit of Lloyd, Székely &amp; Harders 2007 ("Identification of spring parameters for deformable object
    /// simulation"): each spring gets kₑ = c · E · Vₑ / Lₑ², with Vₑ the summed volume of the tetrahedra that contain it
    /// and Lₑ its rest length, and one global dimensionless factor c is fitted so that the network's small-strain
    /// uniaxial response equals E. The fit: a reference box of 4 × 4 × 4 cubes, each split into six tetrahedra around a
    /// diagonal (<see cref="Box"/>), built with the same settings, is stretched along x, y and z in turn (ends held only
    /// along the load, lateral faces free) and solved statically in double by conjugate gradients on the springs'
    /// stiffness matrix K = Σ kₑ nₑnₑᵀ; c is the least-squares fit of the three moduli to E and the residual is their
    /// largest relative deviation from E after the fit (the network's anisotropy).
    /// <para>A spring network cannot represent an arbitrary Poisson ratio: springs only resist changes of length, and
    /// the lateral contraction of the network is set by its geometry, not by ν (regular lattices give about 1/4;
    /// Lloyd et al. show the same for triangle meshes). <see cref="Result.EffectivePoissonRatio"/> reports what the
    /// network does; ν of the material only enters the default damping frequency (through μ). Meshes tetrahedralised
    /// differently from the reference box get the same c and a modulus off by their own anisotropy.</para>
    /// <para>Masses are lumped, mᵢ = ρ Σ V_t / 4. Damping is stiffness-proportional (Rayleigh): cₑ = β kₑ with
    /// β = 2ζ/ω_ref, so a mode of angular frequency ω has damping ratio ζ ω/ω_ref: exactly ζ at ω_ref, more above.</para>
    /// </summary>
    public static class MassSpringCalibration
    {
        /// <summary>What the calibration found.</summary>
        public struct Result
        {
            /// <summary>The fitted factor c of kₑ = c E Vₑ / Lₑ² (dimensionless).</summary>
            public double Factor;
            /// <summary>Largest relative deviation |E_axis / E − 1| of the fitted box's uniaxial moduli along x, y, z (dimensionless).</summary>
            public double Residual;
            /// <summary>The box's uniaxial modulus along x with the fitted factor, divided by E (dimensionless).</summary>
            public double RelativeModulusX;
            /// <summary>The same along y.</summary>
            public double RelativeModulusY;
            /// <summary>The same along z.</summary>
            public double RelativeModulusZ;
            /// <summary>The network's Poisson ratio −ε_lateral / ε_axial, averaged over the three loads (dimensionless).</summary>
            public double EffectivePoissonRatio;
            /// <summary>ω_ref (rad/s): the angular frequency at which the damping ratio ζ holds.</summary>
            public double ReferenceFrequency;
            /// <summary>β = 2ζ / ω_ref (s): dashpot cₑ = β kₑ.</summary>
            public double RayleighBeta;
        }

        /// <summary>Cubes per side of the reference box.</summary>
        public const int ReferenceCells = 4;
        /// <summary>Strain of the reference load (dimensionless); the solve is linear, so it only scales the numbers.</summary>
        public const double ReferenceStrain = 1e-3;

        /// <summary>
        /// Default ω_ref (rad/s) ≈ π √(μ/ρ) / L, L the longest side of the mesh's bounds: the lowest shear mode of a
        /// free body of size L is of this order (a half wavelength across the body at the shear wave speed).
        /// </summary>
        public static double DefaultReferenceFrequency(TetrahedralMesh mesh, in ElasticMaterial material)
        {
            float3 lo = mesh.Positions[0], hi = mesh.Positions[0];
            foreach (float3 p in mesh.Positions)
            {
                lo = math.min(lo, p);
                hi = math.max(hi, p);
            }
            double longest = math.cmax(hi - lo);
            double mu = material.YoungsModulus / (2.0 * (1.0 + material.PoissonRatio));
            return longest > 0.0 ? Math.PI * Math.Sqrt(mu / material.Density) / longest : 0.0;
        }

        /// <summary>
        /// Fits c on the reference box built with <paramref name="settings"/> and sets every spring's stiffness and
        /// damping; false (with an error in <paramref name="issues"/>) when the material is invalid.
        /// </summary>
        /// <param name="referenceFrequency">ω_ref (rad/s); 0 or less = <see cref="DefaultReferenceFrequency"/>.</param>
        public static bool Calibrate(MassSpringNetwork network, TetrahedralMesh mesh, in ElasticMaterial material,
            in MassSpringBuildSettings settings, float referenceFrequency, List<ValidationIssue> issues, out Result result)
        {
            result = default;
            if (!material.IsValid)
            {
                issues.Add(ValidationIssue.Error(MassSpringIssueCode.MaterialInvalid, -1,
                    "The material needs E > 0, 0 ≤ ν < 0.5, ρ > 0 and ζ ≥ 0, all finite."));
                return false;
            }
            result = FitFactor(settings);
            double omega = referenceFrequency > 0f && float.IsFinite(referenceFrequency)
                ? referenceFrequency : DefaultReferenceFrequency(mesh, material);
            result.ReferenceFrequency = omega;
            result.RayleighBeta = omega > 0.0 ? 2.0 * material.DampingRatio / omega : 0.0;
            Apply(network, material.YoungsModulus, result.Factor, result.RayleighBeta);
            return true;
        }

        /// <summary>kₑ = c E Vₑ / Lₑ² and cₑ = β kₑ for every spring of <paramref name="network"/>.</summary>
        public static void Apply(MassSpringNetwork network, double youngsModulus, double factor, double beta)
        {
            for (int e = 0; e < network.Springs.Length; e++)
            {
                ref Spring s = ref network.Springs[e];
                double l = s.RestLength;
                double k = factor * youngsModulus * network.SupportVolumes[e] / (l * l);
                s.Stiffness = (float)k;
                s.Damping = (float)(beta * k);
            }
        }

        /// <summary>Lumped masses mᵢ = ρ Σ V_t / 4 (kg).</summary>
        public static float[] LumpedMasses(MassSpringNetwork network, float density)
        {
            var m = new float[network.NodeCount];
            for (int i = 0; i < m.Length; i++)
                m[i] = density * network.NodeVolumes[i];
            return m;
        }

        /// <summary>The factor c, its residual and the network's Poisson ratio for networks built with <paramref name="settings"/>.</summary>
        public static Result FitFactor(in MassSpringBuildSettings settings)
        {
            TetrahedralMesh box = BoxTetrahedra.Create(new float3(ReferenceCells), new int3(ReferenceCells), new float3(0.5f * ReferenceCells));
            MassSpringNetwork network = MassSpringNetwork.Build(box, settings, new List<ValidationIssue>());
            Apply(network, 1.0, 1.0, 0.0);
            var moduli = new double[3];
            double poisson = 0.0;
            for (int axis = 0; axis < 3; axis++)
            {
                moduli[axis] = UniaxialModulus(box, network.Springs, axis, out double nu, out _);
                poisson += nu / 3.0;
            }
            double sum = 0.0, sumSq = 0.0;
            foreach (double e in moduli)
            {
                sum += e;
                sumSq += e * e;
            }
            double c = sum / sumSq;
            var result = new Result { Factor = c, EffectivePoissonRatio = poisson };
            result.RelativeModulusX = c * moduli[0];
            result.RelativeModulusY = c * moduli[1];
            result.RelativeModulusZ = c * moduli[2];
            foreach (double e in moduli)
                result.Residual = Math.Max(result.Residual, Math.Abs(c * e - 1.0));
            return result;
        }

        /// <summary>
        /// Uniaxial test of a box-shaped network along <paramref name="axis"/> (0 = x): the nodes on the low face of the
        /// axis are held along it, those on the high face displaced by ε × length along it, everything else free except
        /// three components that remove the remaining rigid motions. K u = 0 is solved in double by CG on the free
        /// components; returns σ/ε = (reaction on the high face / cross-section) / ε (Pa per unit of the springs'
        /// stiffness scale), with the lateral contraction as a Poisson ratio and the displacements (m, 3 per node).
        /// </summary>
        public static double UniaxialModulus(TetrahedralMesh box, Spring[] springs, int axis, out double poisson, out double[] displacement)
        {
            int n = box.NodeCount;
            float3 lo = box.Positions[0], hi = box.Positions[0];
            foreach (float3 p in box.Positions)
            {
                lo = math.min(lo, p);
                hi = math.max(hi, p);
            }
            int b = (axis + 1) % 3, c = (axis + 2) % 3;
            double length = hi[axis] - lo[axis];
            double tol = 1e-6 * math.cmax(hi - lo);
            var u = new double[3 * n];
            var free = new bool[3 * n];
            int anchor = -1, second = -1;
            for (int i = 0; i < n; i++)
            {
                float3 p = box.Positions[i];
                bool low = Math.Abs(p[axis] - lo[axis]) <= tol, high = Math.Abs(p[axis] - hi[axis]) <= tol;
                free[3 * i] = free[3 * i + 1] = free[3 * i + 2] = true;
                if (low || high)
                {
                    free[3 * i + axis] = false;
                    u[3 * i + axis] = high ? ReferenceStrain * length : 0.0;
                }
                if (low && Math.Abs(p[b] - lo[b]) <= tol && Math.Abs(p[c] - lo[c]) <= tol)
                    anchor = i;
                if (low && Math.Abs(p[b] - hi[b]) <= tol && Math.Abs(p[c] - lo[c]) <= tol)
                    second = i;
            }
            // Translations across the load and the rotation about the load's axis.
            free[3 * anchor + b] = free[3 * anchor + c] = false;
            free[3 * second + c] = false;

            // r = −K u on the free components; solve K_ff δ = r by CG.
            var ku = new double[3 * n];
            Multiply(box.Positions, springs, u, ku);
            var r = new double[3 * n];
            for (int k = 0; k < r.Length; k++)
                r[k] = free[k] ? -ku[k] : 0.0;
            var d = (double[])r.Clone();
            var q = new double[3 * n];
            double rr = Dot(r, r), r0 = rr;
            for (int it = 0; it < 10 * 3 * n && rr > 1e-26 * r0; it++)
            {
                Multiply(box.Positions, springs, d, q);
                for (int k = 0; k < q.Length; k++)
                    if (!free[k])
                        q[k] = 0.0;
                double alpha = rr / Dot(d, q);
                for (int k = 0; k < u.Length; k++)
                {
                    u[k] += alpha * d[k];
                    r[k] -= alpha * q[k];
                }
                double next = Dot(r, r);
                for (int k = 0; k < d.Length; k++)
                    d[k] = r[k] + next / rr * d[k];
                rr = next;
            }
            Multiply(box.Positions, springs, u, ku);
            double force = 0.0, lowB = 0.0, highB = 0.0, lowC = 0.0, highC = 0.0;
            int nLowB = 0, nHighB = 0, nLowC = 0, nHighC = 0;
            for (int i = 0; i < n; i++)
            {
                float3 p = box.Positions[i];
                if (Math.Abs(p[axis] - hi[axis]) <= tol)
                    force += ku[3 * i + axis];
                if (Math.Abs(p[b] - lo[b]) <= tol) { lowB += u[3 * i + b]; nLowB++; }
                if (Math.Abs(p[b] - hi[b]) <= tol) { highB += u[3 * i + b]; nHighB++; }
                if (Math.Abs(p[c] - lo[c]) <= tol) { lowC += u[3 * i + c]; nLowC++; }
                if (Math.Abs(p[c] - hi[c]) <= tol) { highC += u[3 * i + c]; nHighC++; }
            }
            double widthB = hi[b] - lo[b], widthC = hi[c] - lo[c];
            double strainB = (highB / nHighB - lowB / nLowB) / widthB, strainC = (highC / nHighC - lowC / nLowC) / widthC;
            poisson = -0.5 * (strainB + strainC) / ReferenceStrain;
            displacement = u;
            return force / (widthB * widthC) / ReferenceStrain;
        }

        /// <summary>y = K u with K = Σ kₑ nₑnₑᵀ (rest directions).</summary>
        static void Multiply(float3[] x, Spring[] springs, double[] u, double[] y)
        {
            Array.Clear(y, 0, y.Length);
            foreach (Spring s in springs)
            {
                double dx = (double)x[s.B].x - x[s.A].x, dy = (double)x[s.B].y - x[s.A].y, dz = (double)x[s.B].z - x[s.A].z;
                double l = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                dx /= l; dy /= l; dz /= l;
                int a = 3 * s.A, b = 3 * s.B;
                double along = dx * (u[a] - u[b]) + dy * (u[a + 1] - u[b + 1]) + dz * (u[a + 2] - u[b + 2]);
                double f = s.Stiffness * along;
                y[a] += f * dx; y[a + 1] += f * dy; y[a + 2] += f * dz;
                y[b] -= f * dx; y[b + 1] -= f * dy; y[b + 2] -= f * dz;
            }
        }

        static double Dot(double[] a, double[] b)
        {
            double s = 0.0;
            for (int i = 0; i < a.Length; i++)
                s += a[i] * b[i];
            return s;
        }
    }
}
