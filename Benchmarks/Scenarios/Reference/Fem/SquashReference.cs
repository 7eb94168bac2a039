using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The sampled release of the reference cube: one entry per time step, entry 0 at the release.</summary>
    public sealed class SquashHistory
    {
        /// <summary>Sample interval (s): the time step.</summary>
        public double Interval;
        /// <summary>Time steps per frame: entries 0, StepsPerFrame, 2·StepsPerFrame, … are the frame instants.</summary>
        public int StepsPerFrame;
        /// <summary>Height (m): distance between the area-weighted centroids of the top and bottom faces.</summary>
        public double[] Height;
        /// <summary>RMS over the volume of the displacement from the rest shape (m).</summary>
        public double[] Displacement;
        /// <summary>RMS over the volume of the velocity (m/s).</summary>
        public double[] Speed;
        /// <summary>Newton iterations over the run and whether every step converged.</summary>
        public FemSolveReport Solve;
    }

    /// <summary>
    /// Float64 finite-element reference of the squash-and-release cube: a free cube of edge L, compressed homogeneously to
    /// axial stretch λ along y (lateral stretch s of <see cref="UniaxialNeoHookean"/>, the exact state between frictionless
    /// plates), released at rest with no load and integrated by <see cref="FemNewmark"/> with the Kelvin–Voigt damping of
    /// <see cref="FemViscosity"/>. The initial state and the load (none) are symmetric under the reflections x → −x,
    /// y → −y, z → −z, so the motion is too: the model is the octant [0, L/2]³ (27-node hexahedra, r elements per edge)
    /// with the normal displacement held at zero on the three symmetry planes, which also removes the rigid modes.
    /// RMS displacement and speed use the consistent mass (exact integrals of the Q2 fields); face weights are ∫N_a dA.
    /// The law is the package's Neo-Hookean (<see cref="Law"/>): the squash compresses by half, where the classical
    /// compressible law would keep 1.4 % more volume — a different material, not a discretisation error.
    /// </summary>
    public static class SquashReference
    {
        /// <summary>The hyperelastic law of the squashed cube: the package's stable Neo-Hookean.</summary>
        public const FemMaterialLaw Law = FemMaterialLaw.StableNeoHookean;

        /// <summary>
        /// Default relative residual of each Newmark step (1e-8): tightening it to 1e-10 moves the sampled height and RMS
        /// displacement by less than 4e-10 L (measured over 50 frames at 1 and 2 elements per half edge).
        /// </summary>
        public const double Tolerance = 1e-8;

        /// <summary>The octant model with <paramref name="resolution"/> elements per edge (2r across the whole cube).</summary>
        /// <param name="size">Cube edge L (m).</param>
        /// <param name="youngModulus">E (Pa).</param>
        /// <param name="poissonRatio">ν.</param>
        /// <param name="density">ρ (kg/m³).</param>
        /// <param name="resolution">Elements per half edge, ≥ 1.</param>
        /// <param name="plates">True: u_y also held on the top face (y = L/2), the frictionless plate of the squashed phase.</param>
        public static FemReferenceModel Model(double size, double youngModulus, double poissonRatio, double density, int resolution, bool plates = false)
        {
            if (resolution < 1)
                throw new ArgumentOutOfRangeException(nameof(resolution));
            double half = 0.5 * size;
            FemBoxMesh mesh = FemBoxMesh.Box(half, half, half, resolution, resolution, resolution);
            var fixedDofs = new bool[mesh.DofCount];
            for (int i = 0; i < mesh.NodesX; i++)
            for (int j = 0; j < mesh.NodesY; j++)
            for (int k = 0; k < mesh.NodesZ; k++)
            {
                int node = mesh.Node(i, j, k);
                fixedDofs[node * 3] |= i == 0;
                fixedDofs[node * 3 + 1] |= j == 0 || (plates && j == mesh.NodesY - 1);
                fixedDofs[node * 3 + 2] |= k == 0;
            }
            return new FemReferenceModel(mesh, new FemMaterial(Law, youngModulus, poissonRatio), density, fixedDofs);
        }

        /// <summary>The homogeneous displacement u = (F − I) X with F = diag(s, λ, s) (m, every degree of freedom).</summary>
        public static double[] Homogeneous(FemBoxMesh mesh, double axialStretch, double lateralStretch)
        {
            var u = new double[mesh.DofCount];
            for (int a = 0; a < mesh.NodeCount; a++)
            {
                u[a * 3] = (lateralStretch - 1) * mesh.Positions[a * 3];
                u[a * 3 + 1] = (axialStretch - 1) * mesh.Positions[a * 3 + 1];
                u[a * 3 + 2] = (lateralStretch - 1) * mesh.Positions[a * 3 + 2];
            }
            return u;
        }

        /// <summary>
        /// Static equilibrium of the octant between frictionless plates (top face at u_y = (λ − 1) L/2, free to slide),
        /// from the small-strain guess s = 1 + ν(1 − λ); returns the displacement (m) and the solve report. The exact answer
        /// is <see cref="Homogeneous"/> with the lateral stretch of <see cref="UniaxialNeoHookean"/>, which Q2 elements
        /// represent exactly.
        /// </summary>
        public static (double[] Displacement, FemSolveReport Solve) Squashed(double size, double youngModulus, double poissonRatio,
            double density, int resolution, double axialStretch)
        {
            FemReferenceModel model = Model(size, youngModulus, poissonRatio, density, resolution, plates: true);
            double[] u = Homogeneous(model.Mesh, axialStretch, 1 + poissonRatio * (1 - axialStretch));
            FemSolveReport report = new FemStaticSolver(model).Solve(u, new double[model.Mesh.DofCount]);
            return (u, report);
        }

        /// <summary>Lowest ω (rad/s) of the free cube at rest among the motions with the octant's symmetry that the squash excites (start vector: the homogeneous squash).</summary>
        public static double LowestSymmetricFrequency(double size, double youngModulus, double poissonRatio, double density, int resolution)
        {
            FemReferenceModel model = Model(size, youngModulus, poissonRatio, density, resolution);
            (double w2, _, _) = FemEigen.Lowest(model, new double[model.Mesh.DofCount], Homogeneous(model.Mesh, 0.5, 1.25));
            return Math.Sqrt(w2);
        }

        /// <summary>
        /// The release from the exact squashed state at rest: <paramref name="frames"/> frames of <paramref name="interval"/>
        /// (s), each <paramref name="stepsPerFrame"/> Newmark steps (modified Newton, <see cref="Tolerance"/>), sampled at
        /// every step (entry 0 = the release). Throws if a step does not converge (with fewer than 4 steps per 1/60 s frame,
        /// the sudden release makes Newton fail in the first steps on meshes of 2 or more elements per half edge).
        /// </summary>
        /// <param name="beta">Rayleigh coefficient β (s) of the viscous force.</param>
        /// <param name="tolerance">Relative residual of each step.</param>
        public static SquashHistory Release(double size, double youngModulus, double poissonRatio, double density, int resolution,
            double axialStretch, double beta, double interval, int stepsPerFrame, int frames, double tolerance = Tolerance)
        {
            FemReferenceModel model = Model(size, youngModulus, poissonRatio, density, resolution);
            FemBoxMesh mesh = model.Mesh;
            double lateral = UniaxialNeoHookean.Stress(axialStretch, youngModulus, poissonRatio, Law).LateralStretch;
            var run = new FemNewmark(model, new double[mesh.DofCount], interval / stepsPerFrame, Homogeneous(mesh, axialStretch, lateral),
                null, beta) { ReuseTangent = true, MaxIterations = 40, Tolerance = tolerance };
            FemCsrMatrix mass = model.MassMatrix();
            double[] face = FaceWeights(mesh);
            double octant = mesh.SizeX * mesh.SizeY * mesh.SizeZ * density;
            var free = new double[model.FreeCount];
            var product = new double[model.FreeCount];
            int samples = frames * stepsPerFrame;
            var history = new SquashHistory
            {
                Interval = interval / stepsPerFrame,
                StepsPerFrame = stepsPerFrame,
                Height = new double[samples + 1],
                Displacement = new double[samples + 1],
                Speed = new double[samples + 1],
                Solve = new FemSolveReport { Converged = true },
            };
            for (int k = 0; ; k++)
            {
                history.Height[k] = Height(mesh, run.U, face);
                history.Displacement[k] = Rms(model, mass, run.U, octant, free, product);
                history.Speed[k] = Rms(model, mass, run.V, octant, free, product);
                if (k == samples)
                    break;
                FemSolveReport r = run.Step();
                history.Solve.Steps++;
                history.Solve.NewtonIterations += r.NewtonIterations;
                history.Solve.Factorizations += r.Factorizations;
                if (!r.Converged)
                    throw new InvalidOperationException($"The squash reference's Newmark step {history.Solve.Steps} did not converge (residual {r.RelativeResidual}).");
                history.Solve.RelativeResidual = Math.Max(history.Solve.RelativeResidual, r.RelativeResidual);
            }
            return history;
        }

        /// <summary>Twice the ∫N_a dA-weighted mean y (m) of the top face: the distance between the top and bottom faces' centroids.</summary>
        static double Height(FemBoxMesh mesh, double[] u, double[] face)
        {
            double top = 0, weight = 0;
            for (int a = 0; a < mesh.NodeCount; a++)
                if (face[a] > 0)
                {
                    top += face[a] * (mesh.Positions[a * 3 + 1] + u[a * 3 + 1]);
                    weight += face[a];
                }
            return 2 * top / weight;
        }

        /// <summary>√(∫ρ|f|² dV / ∫ρ dV) = √(fᵀ M f / m) (consistent mass: exact for the Q2 field); f is zero on the fixed degrees of freedom.</summary>
        static double Rms(FemReferenceModel model, FemCsrMatrix mass, double[] f, double totalMass, double[] free, double[] product)
        {
            for (int k = 0; k < free.Length; k++)
                free[k] = f[model.FreeDofs[k]];
            mass.Multiply(free, product);
            double s = 0;
            for (int k = 0; k < free.Length; k++)
                s += free[k] * product[k];
            return Math.Sqrt(s / totalMass);
        }

        /// <summary>∫N_a dA per node over the top face y = L/2 (zero off it).</summary>
        static double[] FaceWeights(FemBoxMesh mesh)
        {
            double[] wx = GridWeights(mesh.NodesX, mesh.ElementSizeX), wz = GridWeights(mesh.NodesZ, mesh.ElementSizeZ);
            var w = new double[mesh.NodeCount];
            for (int i = 0; i < mesh.NodesX; i++)
            for (int k = 0; k < mesh.NodesZ; k++)
                w[mesh.Node(i, mesh.NodesY - 1, k)] = wx[i] * wz[k];
            return w;
        }

        /// <summary>∫N_a of the 1-D quadratic Lagrange basis on a grid of 2n + 1 nodes: h/6 at element ends (2h/6 where two meet), 4h/6 at midpoints.</summary>
        static double[] GridWeights(int nodes, double elementSize)
        {
            var w = new double[nodes];
            for (int e = 0; 2 * e + 2 < nodes; e++)
            {
                w[2 * e] += elementSize / 6;
                w[2 * e + 1] += 4 * elementSize / 6;
                w[2 * e + 2] += elementSize / 6;
            }
            return w;
        }
    }
}
