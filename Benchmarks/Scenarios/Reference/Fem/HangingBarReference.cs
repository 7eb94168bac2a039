using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The static extensions of the reference hanging bar at one resolution, one per load.</summary>
    public struct HangingBarResult
    {
        /// <summary>Extension per load: the mean axial displacement of the free end face (m).</summary>
        public double[] Extensions;
        /// <summary>Elements along the bar and across its section.</summary>
        public int ElementsAlong, ElementsAcross;
        /// <summary>Free degrees of freedom.</summary>
        public int Dofs;
        /// <summary>True when every load's Newton solve converged.</summary>
        public bool Converged;
        /// <summary>Newton iterations over all loads.</summary>
        public int NewtonIterations;
    }

    /// <summary>
    /// Float64 reference for a bar hanging under its own weight: the box [0, L] × [0, h] × [0, h] (axis x), every node of
    /// the x = 0 face clamped, the body force ρ g along +x (the bar's weight pulls it away from the clamp), compressible
    /// Neo-Hookean (<see cref="FemMaterial"/>), 27-node hexahedra (<see cref="FemReferenceModel"/>), statics by Newton
    /// (<see cref="FemStaticSolver"/>). Resolution r = elements across the section; round(L/h · r) along the bar.
    /// The extension is the mean of u_x over the free end face x = L, integrated with the Q2 shape functions (Simpson's
    /// weights 1/6, 2/3, 1/6 per element edge).
    /// <para>The uniform-section curve (<see cref="UniformSectionExtension"/>) is the slender-bar answer: every section in
    /// homogeneous uniaxial tension with free lateral faces, the clamp included. Each section at X carries the weight
    /// below it, so the nominal stress is P(X) = ρ g (L − X) in the reference configuration at any stretch. The clamped
    /// bar is stiffer near the clamp, where its section cannot contract: the difference is the clamp's end effect
    /// (<c>StretchScene</c> reports it).</para>
    /// </summary>
    public static class HangingBarReference
    {
        /// <summary>The model: mesh, material and clamp.</summary>
        /// <param name="length">L (m), along x.</param>
        /// <param name="side">h (m): side of the square section.</param>
        /// <param name="youngModulus">E (Pa).</param>
        /// <param name="poissonRatio">ν.</param>
        /// <param name="density">ρ (kg/m³).</param>
        /// <param name="resolution">Elements across the section (≥ 1).</param>
        public static FemReferenceModel Model(double length, double side, double youngModulus, double poissonRatio, double density, int resolution)
        {
            if (resolution < 1)
                throw new ArgumentOutOfRangeException(nameof(resolution));
            int nx = Math.Max(1, (int)Math.Round(length / side * resolution));
            FemBoxMesh mesh = FemBoxMesh.Box(length, side, side, nx, resolution, resolution);
            var fixedDofs = new bool[mesh.DofCount];
            for (int j = 0; j < mesh.NodesY; j++)
            for (int k = 0; k < mesh.NodesZ; k++)
            {
                int node = mesh.Node(0, j, k);
                for (int c = 0; c < 3; c++)
                    fixedDofs[node * 3 + c] = true;
            }
            return new FemReferenceModel(mesh, new FemMaterial(FemMaterialLaw.NeoHookean, youngModulus, poissonRatio), density, fixedDofs);
        }

        /// <summary>
        /// Static extensions (m) under each acceleration of <paramref name="gravities"/> (m/s², ascending, along the bar),
        /// each solve starting from the previous load's equilibrium.
        /// </summary>
        public static HangingBarResult Extensions(double length, double side, double youngModulus, double poissonRatio, double density,
            double[] gravities, int resolution)
        {
            FemReferenceModel model = Model(length, side, youngModulus, poissonRatio, density, resolution);
            var solver = new FemStaticSolver(model);
            var u = new double[model.Mesh.DofCount];
            var result = new HangingBarResult
            {
                Extensions = new double[gravities.Length],
                ElementsAlong = model.Mesh.ElementsX,
                ElementsAcross = resolution,
                Dofs = model.FreeCount,
                Converged = true,
            };
            for (int i = 0; i < gravities.Length; i++)
            {
                FemSolveReport report = solver.Solve(u, model.BodyForce(new[] { gravities[i], 0, 0 }));
                result.Converged &= report.Converged;
                result.NewtonIterations += report.NewtonIterations;
                result.Extensions[i] = EndFaceMeanAxialDisplacement(model.Mesh, u);
            }
            return result;
        }

        /// <summary>∫ u_x dA / A over the face x = L (m), with the Q2 face quadrature (exact for the element's interpolant).</summary>
        public static double EndFaceMeanAxialDisplacement(FemBoxMesh mesh, ReadOnlySpan<double> u)
        {
            double[] wy = EdgeWeights(mesh.ElementsY), wz = EdgeWeights(mesh.ElementsZ);
            double sum = 0;
            for (int j = 0; j < mesh.NodesY; j++)
            for (int k = 0; k < mesh.NodesZ; k++)
                sum += wy[j] * wz[k] * u[mesh.Node(mesh.NodesX - 1, j, k) * 3];
            return sum;
        }

        /// <summary>Weights (summing to 1) of the 2n + 1 nodes of n equal quadratic elements: ∫ N_a over an element is (1/6, 2/3, 1/6) of it.</summary>
        static double[] EdgeWeights(int elements)
        {
            var w = new double[2 * elements + 1];
            for (int e = 0; e < elements; e++)
            {
                w[2 * e] += 1.0 / 6 / elements;
                w[2 * e + 1] += 2.0 / 3 / elements;
                w[2 * e + 2] += 1.0 / 6 / elements;
            }
            return w;
        }

        /// <summary>
        /// The extension at each load and resolution (ascending, ≥ 3) and, per load, its Richardson estimate
        /// (h = side / resolution). Returns one <see cref="MeshConvergenceResult"/> per load.
        /// </summary>
        public static MeshConvergenceResult[] ExtensionConvergence(double length, double side, double youngModulus, double poissonRatio,
            double density, double[] gravities, int[] resolutions)
        {
            var values = new double[gravities.Length][];
            for (int l = 0; l < gravities.Length; l++)
                values[l] = new double[resolutions.Length];
            var h = new double[resolutions.Length];
            for (int i = 0; i < resolutions.Length; i++)
            {
                HangingBarResult r = Extensions(length, side, youngModulus, poissonRatio, density, gravities, resolutions[i]);
                if (!r.Converged)
                    throw new InvalidOperationException($"The hanging-bar reference did not converge at resolution {resolutions[i]}.");
                for (int l = 0; l < gravities.Length; l++)
                    values[l][i] = r.Extensions[l];
                h[i] = side / resolutions[i];
            }
            var results = new MeshConvergenceResult[gravities.Length];
            for (int l = 0; l < gravities.Length; l++)
                results[l] = new MeshConvergenceResult
                {
                    Resolutions = resolutions, Values = values[l], Estimate = RichardsonExtrapolation.Estimate(h, values[l]),
                };
            return results;
        }

        /// <summary>Extension of the linear bar under its own weight, ρ g L² / (2E) (m): ∫₀ᴸ ρ g (L − X)/E dX.</summary>
        public static double LinearExtension(double length, double youngModulus, double density, double gravity) =>
            density * gravity * length * length / (2 * youngModulus);

        /// <summary>
        /// Exact extension (m) of the uniform-section bar (lateral faces free everywhere) under its own weight:
        /// δ = ∫₀ᴸ (λ(P(X)) − 1) dX with P(X) = ρ g (L − X) and λ(P) the uniaxial Neo-Hookean stretch at nominal stress P
        /// (<see cref="UniaxialNeoHookean"/>). Substituting P and integrating by parts with P = dΨ/dλ along the uniaxial curve:
        /// <code>
        ///   δ = (1/(ρ g)) ∫₀^P_max (λ(P) − 1) dP = [(λ_max − 1) P_max − Ψ(λ_max)] / (ρ g),   P_max = ρ g L, λ_max = λ(P_max)
        /// </code>
        /// (the complementary energy of the clamp section over ρ g), so only λ_max is solved for.
        /// </summary>
        public static double UniformSectionExtension(double length, double youngModulus, double poissonRatio, double density, double gravity)
        {
            double pMax = density * gravity * length;
            if (!(pMax > 0))
                return 0;
            double stretch = StretchAtNominalStress(pMax, youngModulus, poissonRatio);
            double psi = UniaxialNeoHookean.Stress(stretch, youngModulus, poissonRatio).Energy;
            return ((stretch - 1) * pMax - psi) / (density * gravity);
        }

        /// <summary>
        /// The uniaxial stretch λ ≥ 1 whose Neo-Hookean nominal stress is <paramref name="nominalStress"/> (Pa, ≥ 0), by
        /// bisection (P(λ) increases with λ in tension) to 1e-15 relative.
        /// </summary>
        public static double StretchAtNominalStress(double nominalStress, double youngModulus, double poissonRatio)
        {
            if (!(nominalStress >= 0))
                throw new ArgumentOutOfRangeException(nameof(nominalStress));
            double lo = 1, hi = 1 + 2 * nominalStress / youngModulus + 1e-12;
            while (UniaxialNeoHookean.Stress(hi, youngModulus, poissonRatio).NominalStress < nominalStress)
            {
                lo = hi;
                hi *= 2;
            }
            for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++)
            {
                double mid = 0.5 * (lo + hi);
                if (UniaxialNeoHookean.Stress(mid, youngModulus, poissonRatio).NominalStress < nominalStress)
                    lo = mid;
                else
                    hi = mid;
            }
            return 0.5 * (lo + hi);
        }
        /// <summary>
        /// The uniaxial-strain stretch λ ≥ 1 (F = diag(λ, 1, 1): the section held at its rest size, as at the clamp) whose
        /// Neo-Hookean nominal stress P = μ(λ − 1/λ) + λ_L ln λ / λ is <paramref name="nominalStress"/> (Pa, ≥ 0), by bisection.
        /// </summary>
        public static double ConfinedStretchAtNominalStress(double nominalStress, double youngModulus, double poissonRatio)
        {
            if (!(nominalStress >= 0))
                throw new ArgumentOutOfRangeException(nameof(nominalStress));
            var m = new FemMaterial(FemMaterialLaw.NeoHookean, youngModulus, poissonRatio);
            double P(double l) => m.Mu * (l - 1 / l) + m.Lambda * Math.Log(l) / l;
            double lo = 1, hi = 1 + nominalStress / youngModulus + 1e-12;
            while (P(hi) < nominalStress)
            {
                lo = hi;
                hi *= 2;
            }
            for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++)
            {
                double mid = 0.5 * (lo + hi);
                if (P(mid) < nominalStress)
                    lo = mid;
                else
                    hi = mid;
            }
            return 0.5 * (lo + hi);
        }

        /// <summary>
        /// Decay rate × width of the slowest self-equilibrated end disturbance of an elastic strip of width h: its
        /// symmetric Papkovich–Fadle modes decay as e^(−2zX/h) with sin 2z + 2z = 0, whose first root is
        /// z = 2.1062 + 1.1254i, so Re k h = 4.212. A square section of side h is restrained in both lateral directions and is
        /// taken to decay at least as fast, so h / 4.212 is used as the longest decay length of the clamp's disturbance.
        /// </summary>
        public const double StripDecayRateTimesWidth = 4.212;

        /// <summary>
        /// Estimated upper bound on the relative extension deficit 1 − δ_clamped / δ_uniform of the clamped bar against the
        /// uniform-section curve (<see cref="UniformSectionExtension"/>): the clamp holds its section at the rest size, so
        /// there the stretch is the uniaxial-strain one λ_c (<see cref="ConfinedStretchAtNominalStress"/>) instead of the
        /// uniaxial-stress λ_max; by Saint-Venant's principle the disturbance λ_max − λ_c dies out as e^(−kX) away from the
        /// clamp, k ≥ <see cref="StripDecayRateTimesWidth"/> / h, so the extension lost is at most about (λ_max − λ_c) h / 4.212:
        /// <code>
        ///   1 − δ_clamped / δ_uniform ≲ (λ_max − λ_c) h / (4.212 δ_uniform)
        /// </code>
        /// (an estimate: the section-averaged stretch at the clamp is taken as the confined one, the corners' singular
        /// strains are averaged out, and the oscillating part of the decay, which only shortens it, is dropped). The
        /// clamped bar is the stiffer one: in linear elasticity its compliance ∫ ρ g u_x dV is at most ∫ σ²/E dV =
        /// ρ²g²AL³/(3E) of the uniform bar's stress σ = ρ g (L − X), which is statically admissible for the clamped bar
        /// (principle of minimum complementary energy).
        /// </summary>
        public static double EndEffectBound(double length, double side, double youngModulus, double poissonRatio, double density, double gravity)
        {
            double pMax = density * gravity * length;
            double free = StretchAtNominalStress(pMax, youngModulus, poissonRatio);
            double confined = ConfinedStretchAtNominalStress(pMax, youngModulus, poissonRatio);
            return (free - confined) * side / (StripDecayRateTimesWidth * UniformSectionExtension(length, youngModulus, poissonRatio, density, gravity));
        }
    }
}
