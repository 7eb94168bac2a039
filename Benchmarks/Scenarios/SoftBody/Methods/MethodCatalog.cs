using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Every method of the study and the knob values it is swept over: substeps (at most 3 values), and for the implicit and
    /// XPBD FEM variants and mass-spring implicit Euler the resolution (cells across the thickness), the knob that removes
    /// the spatial error. Linear implicit FEM solves with block-Jacobi CG; quadratic FEM with the rest factor
    /// (<see cref="FemRestFactor"/>) and warm starts.
    /// </summary>
    public static class MethodCatalog
    {
        static readonly int[] s_SubstepKnobs = { 4, 16, 64 };
        static readonly int[] s_ExplicitKnobs = { 64, 128, 256 };
        /// <summary>Explicit FEM: at 64 substeps both models reset even in the free run (ζ = 0.01), so the sweep starts at 128.</summary>
        static readonly int[] s_ExplicitFemKnobs = { 128, 256 };
        /// <summary>Mass-spring XPBD: one sweep per substep leaves the network too soft until the substep is small (3× too soft at 16 substeps on the cantilever), so the sweep reaches the substep cap of 256.</summary>
        static readonly int[] s_XpbdKnobs = { 16, 64, 256 };
        /// <summary>Cells across the thickness swept by the resolution variants of FEM (the cantilever has 8n × n × n cells; n = 4 is 825 particles).</summary>
        static readonly int[] s_Resolutions = { 1, 2, 3, 4 };
        /// <summary>
        /// Cells across swept by mass-spring implicit Euler: a step costs ~10× less than implicit FEM's at the same n, so the sweep
        /// goes on to n = 6 (2401 particles), past the point where the calibrated network crosses the reference.
        /// </summary>
        static readonly int[] s_MassSpringResolutions = { 1, 2, 3, 4, 5, 6 };
        /// <summary>Cells across swept by Neo-Hookean XPBD: at a fixed iteration count it turns softer as n grows, so n = 4 adds minutes and no information.</summary>
        static readonly int[] s_XpbdResolutions = { 1, 2, 3 };
        /// <summary>
        /// Cells across swept by Neo-Hookean implicit: its step costs several times co-rotational implicit's (a projected
        /// Hessian per element and a line search), ~1 s per 1/60 s step at n = 3 on the cantilever; at n ≤ 2 it gives
        /// co-rotational's sag to 3 significant digits on the cantilever (small strain), so the sweep stops at 2.
        /// </summary>
        static readonly int[] s_NeoHookeanImplicitResolutions = { 1, 2 };

        /// <summary>
        /// Conjugate-gradient cap and relative residual of the resolution-swept implicit FEM: the defaults (64, 1e-3) stop
        /// short of the solution on the finer beams (the sag then depends on ζ and grows with n), so the sweep solves
        /// each substep to 1e-5 (float32 round-off of the matrix–vector products is ~1e-6 relative).
        /// </summary>
        const int ConvergedCgIterations = 2000;
        const float ConvergedCgTolerance = 1e-5f;
        /// <summary>
        /// Finest resolution of the default run for the resolution-swept linear FEM variants: at 2 cells across one variant's
        /// cantilever point costs ~12 s of evaluation (hundreds of CG iterations per 1/60 s step under block-Jacobi) and shows only
        /// that linear elements lock, which 1 across shows too; <see cref="RunScope.Full"/> goes on.
        /// </summary>
        const int StandardFemResolution = 1;
        /// <summary>
        /// Finest resolution of the default run for quadratic co-rotational FEM: 2 cells across is where it comes within 5 % on the
        /// cantilever at a few ms per step; 3 and 4 (to 1 %) cost 35–185 ms per step and run in <see cref="RunScope.Full"/>.
        /// </summary>
        const int StandardQuadraticResolution = 2;
        /// <summary>
        /// Finest resolution of the default run for mass-spring implicit Euler: 5 cells across is where the calibrated network comes
        /// within 5 % on the cantilever (the study's finding), 6 only shows it crossing the reference.
        /// </summary>
        const int StandardMassSpringResolution = 5;
        /// <summary>XPBD iterations per substep of the resolution-swept Neo-Hookean XPBD (with 64 substeps: 256 projections per step).</summary>
        const int XpbdIterations = 4;

        /// <summary>Cells across swept by the quadratic-element FEM variants.</summary>
        static readonly int[] s_QuadraticResolutions = { 1, 2, 3, 4 };

        static int QuadraticParticles(MethodBodySetup setup)
        {
            QuadraticTetrahedra.Build(setup.Mesh, out float3[] positions, out _, out _);
            return positions.Length;
        }

        /// <summary>The variants in report order.</summary>
        public static IReadOnlyList<MethodVariant> Variants { get; } = new List<MethodVariant>
        {
            new MethodVariant("SM rigid", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Rigid, k, h)),
            new MethodVariant("SM linear", "substeps", s_SubstepKnobs, new[] { 4 },
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Linear, k, h)),
            new MethodVariant("SM quadratic", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Quadratic, k, h)),
            new MethodVariant("MS symplectic Euler", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.SymplecticEuler, k)),
            new MethodVariant("MS Verlet", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.Verlet, k)),
            new MethodVariant("MS implicit Euler", "substeps", new[] { 4 }, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.ImplicitEuler, k), s_MassSpringResolutions,
                standardMaxResolution: StandardMassSpringResolution),
            new MethodVariant("MS XPBD", "substeps", s_XpbdKnobs, new[] { 4 },
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.Xpbd, k)),
            new MethodVariant("FEM co-rotational explicit", "substeps", s_ExplicitFemKnobs, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.SymplecticEuler, k)),
            new MethodVariant("FEM co-rotational implicit", "substeps", new[] { 1 }, new[] { 1 },
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, k, ConvergedCgIterations,
                    ConvergedCgTolerance), s_Resolutions, standardMaxResolution: StandardFemResolution),
            new MethodVariant(FemMethodBody.FamilyName(FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, FemElementOrder.Quadratic),
                "substeps", new[] { 1, 2 }, new[] { 1 },
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, k, ConvergedCgIterations,
                    ConvergedCgTolerance, order: FemElementOrder.Quadratic, restFactor: true), s_QuadraticResolutions,
                standardMaxResolution: StandardQuadraticResolution, particleCount: QuadraticParticles, standardKnobs: new[] { 1 }),
            new MethodVariant("FEM Neo-Hookean implicit", "substeps", new[] { 1 }, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.ImplicitEuler, k, ConvergedCgIterations,
                    ConvergedCgTolerance), s_NeoHookeanImplicitResolutions, standardMaxResolution: StandardFemResolution),
            new MethodVariant(FemMethodBody.FamilyName(FemMaterialModel.NeoHookean, FemIntegrator.ImplicitEuler, FemElementOrder.Quadratic),
                "substeps", new[] { 2 }, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.ImplicitEuler, k, ConvergedCgIterations,
                    ConvergedCgTolerance, order: FemElementOrder.Quadratic, restFactor: true), s_QuadraticResolutions,
                particleCount: QuadraticParticles, standardKnobs: new int[0]),
            new MethodVariant("FEM Neo-Hookean explicit", "substeps", s_ExplicitFemKnobs, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.SymplecticEuler, k)),
            new MethodVariant("FEM Neo-Hookean XPBD", "substeps", new[] { 64 }, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.Xpbd, k, iterations: XpbdIterations), s_XpbdResolutions,
                standardMaxResolution: StandardFemResolution),
            new MethodVariant("Hybrid SM + MS XPBD", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new HybridMethodBody(s, k, h)),
        };

        /// <summary>The variant of the study whose finest setting serves as the reference where a scene has no independent one; null when none is available.</summary>
        public static MethodVariant ReferenceVariant => null;
    }
}
