using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using static SoftBodyDynamics.Tests.Solvers.DoubleMatrix3;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Implicit Euler of the stable Neo-Hookean model: its tangent is the energy Hessian (finite differences of the force),
    /// projected to positive semi-definite; stiff bodies are stable at 1/60 s with one substep; small-load statics match
    /// the co-rotational model; element passes have the same bits for any split; Newton iterations converge.
    /// </summary>
    public class FemNeoHookeanImplicitTests
    {
        const float Mu = 3.4e3f, Lambda = 3.1e4f;
        static float LambdaSnh => FemElasticity.NeoHookeanLambda(Mu, Lambda);

        static readonly float3[] s_Rest =
        {
            new float3(0f, 0f, 0f), new float3(0.1f, 0.01f, 0f), new float3(0.02f, 0.09f, 0.01f), new float3(0.01f, 0.02f, 0.11f),
        };

        static TetElement Element()
        {
            var dm = new float3x3(s_Rest[1] - s_Rest[0], s_Rest[2] - s_Rest[0], s_Rest[3] - s_Rest[0]);
            return new TetElement { Nodes = new int4(0, 1, 2, 3), InverseRestShape = math.inverse(dm), RestVolume = math.determinant(dm) / 6f };
        }

        /// <summary>A random F with singular values near 1 (±<paramref name="spread"/>), mirrored when <paramref name="inverted"/>.</summary>
        static float3x3 RandomF(System.Random random, float spread, bool inverted)
        {
            float R() => (float)(random.NextDouble() * 2 - 1);
            var f = new float3x3(1f + spread * R(), spread * R(), spread * R(), spread * R(), 1f + spread * R(), spread * R(),
                spread * R(), spread * R(), 1f + spread * R());
            if (inverted)
                f.c0 = -f.c0;
            return f;
        }

        static float3x3 PolarRotation(in float3x3 f)
        {
            quaternion q = quaternion.identity;
            RotationExtraction.Extract(f, ref q, 100);
            return new float3x3(q);
        }

        // ---- float64 reference force

        /// <summary>Nodal forces H = −V P Dm⁻ᵀ of the stable Neo-Hookean P = μF + λ(J − α) cof F, all in double.</summary>
        static double[,] ForcesDouble(double[,] x)
        {
            var ds = new double[3, 3];
            var dm = new double[3, 3];
            for (int c = 0; c < 3; c++)
                for (int r = 0; r < 3; r++)
                {
                    ds[r, c] = x[c + 1, r] - x[0, r];
                    dm[r, c] = (double)s_Rest[c + 1][r] - s_Rest[0][r];
                }
            double[,] dmInv = Inverse(dm);
            double[,] f = Mul(ds, dmInv);
            double mu = Mu, lambda = (double)Lambda + Mu, alpha = 1 + mu / lambda;
            double[,] cof = Cofactor(f);
            double j = f[0, 0] * cof[0, 0] + f[1, 0] * cof[1, 0] + f[2, 0] * cof[2, 0];
            double volume = Det(dm) / 6;
            var forces = new double[4, 3];
            for (int node = 1; node < 4; node++)
                for (int r = 0; r < 3; r++)
                {
                    // H[r, node − 1] = −V Σ_c P[r, c] Dm⁻¹[node − 1, c].
                    double h = 0;
                    for (int c = 0; c < 3; c++)
                        h -= volume * (mu * f[r, c] + lambda * (j - alpha) * cof[r, c]) * dmInv[node - 1, c];
                    forces[node, r] = h;
                    forces[0, r] -= h;
                }
            return forces;
        }

        /// <summary>
        /// The exact (unprojected) tangent's force change −K u of an element against the central difference of the float64
        /// force, −K u ≈ (f(x + δu) − f(x − δu)) / 2δ, for random F (inverted too) and directions u.
        /// </summary>
        [Test]
        public void HessianProduct_MatchesFiniteDifferenceOfForce([Values(1, 2, 3)] int seed, [Values] bool inverted)
        {
            var random = new System.Random(seed);
            TetElement element = Element();
            double worst = 0, largest = 0;
            for (int trial = 0; trial < 5; trial++)
            {
                float3x3 f0 = RandomF(random, 0.3f, inverted);
                var x = new float3[4];
                var u = new float3[4];
                for (int i = 0; i < 4; i++)
                {
                    x[i] = math.mul(f0, s_Rest[i]) + new float3(0.3f, -0.2f, 0.1f);
                    u[i] = new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f) * 0.1f;
                }
                float3x3 f = FemElasticity.DeformationGradient(x[0], x[1], x[2], x[3], element.InverseRestShape);
                Assert.That(math.determinant(f) > 0f, Is.EqualTo(!inverted));
                float3x3 r = PolarRotation(f);
                NeoHookeanTangent exact = NeoHookeanTangent.Compute(f, r, Mu, LambdaSnh, false);
                float3x3 du = FemElasticity.DeformationGradient(u[0], u[1], u[2], u[3], element.InverseRestShape);
                var slots = new float3[4];
                FemElasticity.NodalForces(exact.StressDifferential(r, du), element, slots);

                // Central difference with δ = 1e-6 (u ~ 0.05 m: 5e-8 m steps on 0.1 m edges): the force is a polynomial of
                // degree 5 in x, truncation ~ δ² f''' ~ 1e-12 relative, round-off ~ 1e-16/1e-6 = 1e-10 relative.
                const double delta = 1e-6;
                var plus = new double[4, 3];
                var minus = new double[4, 3];
                for (int i = 0; i < 4; i++)
                    for (int a = 0; a < 3; a++)
                    {
                        plus[i, a] = (double)x[i][a] + delta * u[i][a];
                        minus[i, a] = (double)x[i][a] - delta * u[i][a];
                    }
                double[,] fp = ForcesDouble(plus), fm = ForcesDouble(minus);
                for (int i = 0; i < 4; i++)
                    for (int a = 0; a < 3; a++)
                    {
                        double reference = (fp[i, a] - fm[i, a]) / (2 * delta);
                        largest = Math.Max(largest, Math.Abs(reference));
                        worst = Math.Max(worst, Math.Abs(slots[i][a] - reference));
                    }
            }
            TestContext.WriteLine($"largest |K u| {largest:G4} N, worst difference {worst:G3} N ({worst / largest:G3} relative)");
            // float32: F from positions rounded at 1e-7 of |x| ~ 0.4 m on 0.1 m edges (~5e-7 of F), the rotation's residual
            // (tolerance 1e-6 rad, its skew part dropped from RᵀF), the Jacobi frame (~1e-7) and a dozen products, each term
            // ~ (λ + μ)|F|² |δF| with |F| ≤ 1.6: ~1e-5 of the largest nodal value at most. Measured ≤ 9e-7.
            Assert.That(worst, Is.LessThan(2e-5 * largest));
        }

        /// <summary>
        /// Ψ(F + D) − Ψ(F) of the line search, formed without either value, against the float64 difference, for steps from
        /// 1e-1 down to 1e-5 of F (where the two float32 energies would cancel to a few digits).
        /// </summary>
        [Test]
        public void EnergyChange_MatchesDoubleDifference([Values(1, 2, 3)] int seed)
        {
            var random = new System.Random(seed);
            float R() => (float)(random.NextDouble() * 2 - 1);
            // Ψ(F + s D) in double, the sum formed in double.
            double Psi(float3x3 m, float3x3 dm, double s)
            {
                double mu = Mu, lambda = (double)LambdaSnh, alpha = 1 + mu / lambda, ic = 0;
                var md = new double[3, 3];
                for (int c = 0; c < 3; c++)
                    for (int r = 0; r < 3; r++)
                    {
                        md[r, c] = m[c][r] + s * dm[c][r];
                        ic += md[r, c] * md[r, c];
                    }
                double j = Det(md) - alpha;
                return 0.5 * mu * (ic - 3) + 0.5 * lambda * j * j;
            }
            double worst = 0;
            foreach (bool inverted in new[] { false, true })
                foreach (float scale in new[] { 1e-1f, 1e-3f, 1e-5f })
                {
                    float3x3 f = RandomF(random, 0.3f, inverted);
                    float3x3 d = scale * new float3x3(R(), R(), R(), R(), R(), R(), R(), R(), R());
                    double reference = Psi(f, d, 1) - Psi(f, d, 0);
                    double change = FemElasticity.NeoHookeanEnergyChange(f, d, Mu, LambdaSnh);
                    // Relative to the size of its terms, ‖P‖‖D‖ + (μ + λ)‖D‖² (Frobenius; the change itself can vanish).
                    float3x3 p = FemElasticity.NeoHookeanStress(f, Mu, LambdaSnh);
                    double dd = DoubleDot(d, d);
                    double size = Math.Sqrt(DoubleDot(p, p) * dd) + (Mu + LambdaSnh) * dd;
                    worst = Math.Max(worst, Math.Abs(change - reference) / size);
                }
            TestContext.WriteLine($"worst |ΔΨ − ΔΨ_double| {worst:G3} of ‖P‖‖D‖ + (μ + λ)‖D‖²");
            // Each term is a float32 product of factors known to ~1e-7, a dozen of them; the double reference cancels to
            // ~1e-16 |Ψ| / |ΔΨ| ≤ 1e-10 at the smallest step. Measured ≤ 4e-7; bound 1e-5.
            Assert.That(worst, Is.LessThan(1e-5));
        }

        static float DoubleDot(in float3x3 a, in float3x3 b) => FemElasticity.DoubleDot(a, b);

        /// <summary>
        /// The projected tangent K⁺ is positive semi-definite where the exact Hessian K is not (compressed or inverted
        /// elements), K⁺ − K is positive semi-definite (only negative eigenvalues were raised), and K⁺ = K where K is
        /// already semi-definite (moderate stretch of a compressible material: every eigenvalue positive).
        /// </summary>
        [Test]
        public void ProjectedTangent_IsSemiDefinite_AndExactWhereTheHessianIs([Values(1, 2, 3)] int seed)
        {
            var random = new System.Random(seed);
            float R() => (float)(random.NextDouble() * 2 - 1);
            float3x3 RandomMatrix() => new float3x3(R(), R(), R(), R(), R(), R(), R(), R(), R());
            float scale = Mu + LambdaSnh;
            // float32 round-off of the quadratic forms: ~1e-6 of (λ + 2μ)|F|²|δF|² with |F| ≲ 2: 1e-5 scale is ample.
            float tolerance = 1e-5f * scale;
            float mostNegativeExact = 0f;
            foreach (bool inverted in new[] { false, true })
            {
                // Compressed to ~60 % volume (or inverted): the twist modes' μ + λ(J − α)σ and the scaling block go negative.
                float3x3 f = math.mul(new float3x3(quaternion.AxisAngle(math.normalize(new float3(R(), R(), 1f)), 2f * R())),
                    RandomF(random, 0.1f, inverted) * 0.85f);
                float3x3 r = PolarRotation(f);
                NeoHookeanTangent exact = NeoHookeanTangent.Compute(f, r, Mu, LambdaSnh, false);
                NeoHookeanTangent projected = NeoHookeanTangent.Compute(f, r, Mu, LambdaSnh, true);
                for (int trial = 0; trial < 200; trial++)
                {
                    float3x3 df = RandomMatrix();
                    float k = DoubleDot(df, exact.StressDifferential(r, df));
                    float kPlus = DoubleDot(df, projected.StressDifferential(r, df));
                    mostNegativeExact = math.min(mostNegativeExact, k / scale);
                    Assert.That(kPlus, Is.GreaterThan(-tolerance), "K⁺ is positive semi-definite");
                    Assert.That(kPlus - k, Is.GreaterThan(-tolerance), "K⁺ − K is positive semi-definite");
                }
            }
            TestContext.WriteLine($"most negative δF:KδF of the exact Hessian {mostNegativeExact:G3} (μ + λ)");
            Assert.That(mostNegativeExact, Is.LessThan(-0.01f), "the exact Hessian is indefinite there (the projection is exercised)");

            // Moderate stretch, ν = 0.3 (λ_snh = 2.5 μ): twist μ + λ(J − α)σ > 0, flip > 0, the scaling block positive definite.
            float mu = 1f, lambdaSnh = 2.5f;
            float3x3 stretch = math.mul(new float3x3(quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.4f)),
                new float3x3(1.1f, 0.02f, 0f, 0.02f, 1.05f, 0.01f, 0f, 0.01f, 1.08f));
            float3x3 rs = PolarRotation(stretch);
            NeoHookeanTangent e1 = NeoHookeanTangent.Compute(stretch, rs, mu, lambdaSnh, false);
            NeoHookeanTangent p1 = NeoHookeanTangent.Compute(stretch, rs, mu, lambdaSnh, true);
            for (int trial = 0; trial < 20; trial++)
            {
                float3x3 df = RandomMatrix();
                float3x3 difference = p1.StressDifferential(rs, df) - e1.StressDifferential(rs, df);
                // Identical arithmetic once no eigenvalue is clamped.
                Assert.That(Matrix3.MaxAbs(difference), Is.EqualTo(0f));
            }
        }

        /// <summary>At rest (F a rotation Q) the projected tangent is linear elasticity: the warped stiffness Q K₀ Qᵀ with the linear λ.</summary>
        [Test]
        public void ProjectedTangent_AtRest_IsLinearElasticity_AndFreeForRotations()
        {
            var q = new float3x3(quaternion.AxisAngle(math.normalize(new float3(0.3f, -1f, 0.5f)), 1.3f));
            float3x3 r = PolarRotation(q);
            NeoHookeanTangent t = NeoHookeanTangent.Compute(q, r, Mu, LambdaSnh, true);
            var random = new System.Random(11);
            float R() => (float)(random.NextDouble() * 2 - 1);
            float worst = 0f, spin = 0f;
            for (int trial = 0; trial < 20; trial++)
            {
                var df = new float3x3(R(), R(), R(), R(), R(), R(), R(), R(), R());
                float3x3 linear = FemElasticity.WarpedStressDifferential(q, df, Mu, Lambda);
                worst = math.max(worst, Matrix3.MaxAbs(t.StressDifferential(r, df) - linear));
                // A rigid spin: δF = W Q, W skew.
                var w = new float3x3(0f, -df.c0.z, df.c0.y, df.c0.z, 0f, -df.c0.x, -df.c0.y, df.c0.x, 0f);
                spin = math.max(spin, Matrix3.MaxAbs(t.StressDifferential(r, math.mul(w, q))));
            }
            TestContext.WriteLine($"|δP − δP_linear| {worst:G3} Pa, |δP(spin)| {spin:G3} Pa, λ + 2μ = {Lambda + 2f * Mu:G3} Pa");
            // Round-off: ~10 float32 products of size (λ + 2μ)|δF| ≤ 3.8e4 × 3: ~1e-6 relative, 1e-4 absolute per unit; 0.05 Pa bound.
            Assert.That(worst, Is.LessThan(0.05f));
            Assert.That(spin, Is.LessThan(0.05f));
        }

        // ---- bodies

        static FemParameters Implicit(FemMaterialModel model, int substeps, float3 gravity)
        {
            FemParameters p = FemParameters.Default;
            p.Model = model;
            p.Integrator = FemIntegrator.ImplicitEuler;
            p.Body.Substeps = substeps;
            p.Body.Acceleration = gravity;
            p.Body.SleepSpeed = 0f;
            p.CgIterations = 500;
            p.CgTolerance = 1e-4f;
            return p;
        }

        /// <summary>
        /// The energy internal forces can dissipate (J): the elastic energy above rest, Σ V (Ψ(F) − Ψ(I)), plus the kinetic
        /// energy less that of the rigid motion with the same momentum P and angular momentum L (both conserved by internal
        /// forces): ½|P|²/M + ½ Lᵀ I⁻¹ L, I the inertia tensor about the centre of mass. In double.
        /// </summary>
        static double DeformationEnergy(FemTestBody body)
        {
            float3[] x = body.Positions, v = body.Velocities;
            float[] m = body.Data.Masses;
            double mass = 0, kinetic = 0;
            var c = new double[3];
            var p = new double[3];
            for (int i = 0; i < x.Length; i++)
            {
                mass += m[i];
                kinetic += 0.5 * m[i] * math.lengthsq(v[i]);
                for (int a = 0; a < 3; a++)
                {
                    c[a] += m[i] * (double)x[i][a];
                    p[a] += m[i] * (double)v[i][a];
                }
            }
            var l = new double[3];
            var inertia = new double[3, 3];
            for (int i = 0; i < x.Length; i++)
            {
                var r = new double[3];
                var u = new double[3];
                for (int a = 0; a < 3; a++)
                {
                    r[a] = x[i][a] - c[a] / mass;
                    u[a] = v[i][a] - p[a] / mass;
                }
                l[0] += m[i] * (r[1] * u[2] - r[2] * u[1]);
                l[1] += m[i] * (r[2] * u[0] - r[0] * u[2]);
                l[2] += m[i] * (r[0] * u[1] - r[1] * u[0]);
                double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        inertia[a, b] += m[i] * ((a == b ? rr : 0.0) - r[a] * r[b]);
            }
            double[,] inverse = Inverse(inertia);
            double spin = 0;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    spin += 0.5 * l[a] * inverse[a, b] * l[b];
            double translation = 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / mass;
            double elastic = 0;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(body.Data.Mu, body.Data.Lambda);
            foreach (TetElement t in body.Data.Elements)
            {
                int4 n = t.Nodes;
                float3x3 f = FemElasticity.DeformationGradient(x[n.x], x[n.y], x[n.z], x[n.w], t.InverseRestShape);
                elastic += t.RestVolume * (double)FemElasticity.NeoHookeanEnergyChange(float3x3.identity, f - float3x3.identity, body.Data.Mu, lambdaSnh);
            }
            return elastic + kinetic - translation - spin;
        }

        /// <summary>
        /// A stiff (E = 10 MPa) single tetrahedron or 2×2×2-cube box, kicked with random velocities or squashed to half its
        /// height, at 1/60 s with one substep: far above the explicit bound (symplectic Euler at that step is reset by the
        /// guard), the implicit step stays finite, un-inverted, and loses energy.
        /// </summary>
        [Test]
        public void StiffBody_StableAtOneSixtiethWithOneSubstep([Values] bool singleTet, [Values] bool squash)
        {
            TetrahedralMesh mesh = singleTet
                ? new TetrahedralMesh((float3[])s_Rest.Clone(), new[] { new int4(0, 1, 2, 3) })
                : FemTestBodies.Box(2, 2, 2, new float3(0.2f));
            FemModelData data = FemTestBodies.Bake(mesh, new ElasticMaterial(1e7f, 0.3f, 1000f, 0.1f));
            const float dt = 1f / 60f;
            float hMax = FemStability.MaxStableStep(data.AsModel(), FemMaterialModel.NeoHookean);
            Assert.That(hMax, Is.LessThan(0.1f * dt), "the explicit bound is far below the step");

            void Disturb(FemTestBody b)
            {
                var random = new System.Random(4);
                for (int i = 0; i < b.Positions.Length; i++)
                {
                    if (squash)
                        b.Positions[i].y = 0.5f * b.Positions[i].y;
                    else
                        b.Velocities[i] = new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f,
                            (float)random.NextDouble() - 0.5f);
                }
            }

            var body = new FemTestBody(data, Implicit(FemMaterialModel.NeoHookean, 1, float3.zero));
            float restVolume = body.Volume();
            Disturb(body);
            double start = DeformationEnergy(body);
            for (int step = 0; step < 60; step++)
            {
                FemStepReport report = body.Step(dt);
                Assert.That(report.Step.Reset, Is.False, $"reset at step {step}");
                Assert.That(report.IntegratorFallback, Is.False);
                Assert.That(report.Integrator, Is.EqualTo(FemIntegrator.ImplicitEuler));
            }
            double end = DeformationEnergy(body);
            TestContext.WriteLine($"h_max {hMax:G3} s = dt / {dt / hMax:G3}; energy {start:G4} J → {end:G4} J; " +
                                  $"min det F {body.MinDeterminant():G4}, volume {body.Volume() / restVolume:G5} of rest");
            Assert.That(body.AllFinite());
            Assert.That(body.MinDeterminant(), Is.GreaterThan(0f));
            // Backward Euler multiplies a mode's energy by 1/(1 + h²ω²) per step (less with its damping); the slowest mode of
            // these bodies has hω > 1 at this step, so 60 steps leave far less than 1 % (measured ≤ 5e-5, round-off of the
            // rigid-motion subtraction included).
            Assert.That(end, Is.LessThan(0.01 * start), "backward Euler dissipates the deformation");
            Assert.That(math.abs(body.Volume() / restVolume - 1f), Is.LessThan(0.05f));

            // The same disturbance under symplectic Euler at this step blows up and the guard resets the body.
            FemParameters explicitP = Implicit(FemMaterialModel.NeoHookean, 1, float3.zero);
            explicitP.Integrator = FemIntegrator.SymplecticEuler;
            var explicitBody = new FemTestBody(data, explicitP);
            Disturb(explicitBody);
            bool reset = false;
            for (int step = 0; step < 60 && !reset; step++)
                reset = explicitBody.Step(dt).Step.Reset;
            Assert.That(reset, Is.True, "symplectic Euler is unstable at this step");
        }

        /// <summary>Static tip sag (m) of a 1 m × 0.1 m × 0.1 m beam (10×1×1 cubes, E 100 MPa, ν 0.25), x = 0 pinned, under gravity.</summary>
        static double CantileverSag(FemMaterialModel model)
        {
            const float length = 1f, side = 0.1f;
            TetrahedralMesh mesh = FemTestBodies.Box(10, 1, 1, new float3(length, side, side));
            var pinned = new bool[mesh.NodeCount];
            for (int i = 0; i < pinned.Length; i++)
                pinned[i] = mesh.Positions[i].x == 0f;
            FemModelData data = FemTestBodies.Bake(mesh, new ElasticMaterial(1e8f, 0.25f, 1000f, 0f), pinned);
            FemParameters p = Implicit(model, 1, new float3(0f, -9.81f, 0f));
            p.CgIterations = 2000;
            p.CgTolerance = 1e-6f;
            var body = new FemTestBody(data, p);
            float3 startCenter = body.Status.LocalCenter;
            // Steps of 0.2 s: backward Euler damps the first mode (5 Hz, hω ≈ 6) by ~40× per step, so 15 steps reach the
            // static state to the CG tolerance. (Steps of 1 s follow the element rotations only to first order and leave
            // a ±3 % step-to-step jitter of the sag with either model.)
            for (int step = 0; step < 15; step++)
                body.Step(0.2f);
            return body.MeanSag(mesh, length, startCenter);
        }

        /// <summary>
        /// At small load (tip sag ≈ 0.35 % of the length) both models are linear elasticity to first order (the Neo-Hookean λ
        /// is re-parameterised to match at rest), and implicit Euler settles on the static state f(x) + Mg = 0 of each. The
        /// models differ at second order in the strain, so the sags differ by a fraction of order the largest strain,
        /// ε_max = M c / (E I) = (ρ g A L²/2)(h/2)/(E h⁴/12) ≈ 2.9e-3 at the clamp, which is the bound; the CG tolerance 1e-6
        /// adds step-to-step jitter of a few 1e-4 (measured 3.5e-5 and 3.9e-4 on two node numberings of the same mesh).
        /// </summary>
        [Test]
        public void Cantilever_SmallLoadStaticSag_MatchesCoRotational()
        {
            double neoHookean = CantileverSag(FemMaterialModel.NeoHookean), coRotational = CantileverSag(FemMaterialModel.CoRotational);
            double relative = neoHookean / coRotational - 1.0;
            const double side = 0.1, moment = 1000.0 * 9.81 * side * side * 1.0 / 2.0;
            double strain = moment * (side / 2) / (1e8 * side * side * side * side / 12.0);
            TestContext.WriteLine($"tip sag: Neo-Hookean {neoHookean:G6} m, co-rotational {coRotational:G6} m, relative difference {relative:G3}, ε_max {strain:G3}");
            Assert.That(coRotational, Is.GreaterThan(1e-3), "the beam sags");
            Assert.That(Math.Abs(relative), Is.LessThan(strain));
        }

        static (uint, uint, uint) Bits(float3 v) => (math.asuint(v.x), math.asuint(v.y), math.asuint(v.z));

        /// <summary>
        /// The tangent pass (forces, rotations, tangents), the stiffness product and the line search's energy pass, run in batches of 1, 7 and 33 elements
        /// and nodes in reverse order, give the bits of one whole-range run (the pattern of
        /// FemBakeAndDeterminismTests.ElementForces_SameBits_ForAnyBatchSplitAndOrder).
        /// </summary>
        [Test]
        public void TangentAndStiffnessPasses_SameBits_ForAnyBatchSplitAndOrder()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(3, 3, 2, new float3(0.3f, 0.3f, 0.2f)), new ElasticMaterial(1e4f, 0.45f, 1000f, 0.1f));
            var random = new System.Random(9);
            var x = new float3[data.RestPositions.Length];
            var u = new float3[x.Length];
            for (int i = 0; i < x.Length; i++)
            {
                x[i] = data.RestPositions[i] + 0.03f * new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f);
                u[i] = new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f);
            }
            (float3[] f, float3[] ku, float3[] tangents, float3[] energies) Run(int batch, bool reverse)
            {
                FemModel model = data.AsModel();
                var rotations = new quaternion[model.ElementCount];
                Array.Fill(rotations, quaternion.identity);
                var slots = new float3[4 * model.ElementCount];
                var tangents = new float3[NeoHookeanTangent.Float3Count * model.ElementCount];
                var f = new float3[model.ParticleCount];
                var ku = new float3[model.ParticleCount];
                int elementBatches = (model.ElementCount + batch - 1) / batch, nodeBatches = (model.ParticleCount + batch - 1) / batch;
                for (int b = 0; b < elementBatches; b++)
                {
                    int k = reverse ? elementBatches - 1 - b : b;
                    FemForces.NeoHookeanTangents(model, x, default, 0f, rotations, 20, tangents, slots, k * batch, math.min(model.ElementCount, (k + 1) * batch));
                }
                for (int b = 0; b < nodeBatches; b++)
                {
                    int k = reverse ? nodeBatches - 1 - b : b;
                    FemForces.Gather(model, slots, f, k * batch, math.min(model.ParticleCount, (k + 1) * batch));
                }
                for (int b = 0; b < elementBatches; b++)
                {
                    int k = reverse ? elementBatches - 1 - b : b;
                    FemForces.NeoHookeanStiffness(model, rotations, tangents, u, slots, k * batch, math.min(model.ElementCount, (k + 1) * batch));
                }
                for (int b = 0; b < nodeBatches; b++)
                {
                    int k = reverse ? nodeBatches - 1 - b : b;
                    FemForces.Gather(model, slots, ku, k * batch, math.min(model.ParticleCount, (k + 1) * batch));
                }
                // The line search's per-element energy changes (slot 4e).
                for (int b = 0; b < elementBatches; b++)
                {
                    int k = reverse ? elementBatches - 1 - b : b;
                    FemForces.NeoHookeanEnergyChange(model, x, u, u, 0.01f, 0.5f, slots, k * batch, math.min(model.ElementCount, (k + 1) * batch));
                }
                var energies = new float3[model.ElementCount];
                for (int e = 0; e < energies.Length; e++)
                    energies[e] = slots[4 * e];
                return (f, ku, tangents, energies);
            }
            var whole = Run(100000, false);
            foreach (int batch in new[] { 1, 7, 33 })
            {
                var split = Run(batch, true);
                for (int i = 0; i < whole.f.Length; i++)
                {
                    Assert.That(Bits(split.f[i]), Is.EqualTo(Bits(whole.f[i])), $"force, node {i}, batch {batch}");
                    Assert.That(Bits(split.ku[i]), Is.EqualTo(Bits(whole.ku[i])), $"K u, node {i}, batch {batch}");
                }
                for (int i = 0; i < whole.tangents.Length; i++)
                    Assert.That(Bits(split.tangents[i]), Is.EqualTo(Bits(whole.tangents[i])), $"tangent float3 {i}, batch {batch}");
                for (int e = 0; e < whole.energies.Length; e++)
                    Assert.That(Bits(split.energies[e]), Is.EqualTo(Bits(whole.energies[e])), $"energy change, element {e}, batch {batch}");
            }
        }

        [Test]
        public void Step_SameInput_SameBits()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), new ElasticMaterial(1e4f, 0.45f, 1000f, 0.1f));
            FemParameters p = Implicit(FemMaterialModel.NeoHookean, 2, new float3(0f, -9.81f, 0f));
            p.NewtonIterations = 2;
            var colliders = new[] { ColliderShape.Plane(new float3(0f, -0.3f, 0f), new float3(0f, 1f, 0f)) };
            FemTestBody a = new FemTestBody(data, p), b = new FemTestBody(data, p);
            for (int step = 0; step < 30; step++)
            {
                a.Step(1f / 60f, colliders);
                b.Step(1f / 60f, colliders);
            }
            for (int i = 0; i < a.Positions.Length; i++)
                Assert.That(Bits(a.Positions[i]), Is.EqualTo(Bits(b.Positions[i])));
        }

        /// <summary>
        /// Newton iterations converge to the nonlinear backward-Euler step: the residual M(v⁺ − v) − h f(x + h v⁺) (no damping)
        /// of one substep from a body stretched by 30 % and sheared falls as <see cref="FemParameters.NewtonIterations"/> grows.
        /// </summary>
        [Test]
        public void NewtonIterations_ReduceTheBackwardEulerResidual()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), new ElasticMaterial(1e5f, 0.3f, 1000f, 0f));
            int n = data.RestPositions.Length, e = data.Elements.Length;
            var x0 = new float3[n];
            var shear = new float3x3(1.3f, 0.15f, 0f, 0f, 0.95f, 0.1f, 0f, 0f, 1f);
            for (int i = 0; i < n; i++)
                x0[i] = math.mul(shear, data.RestPositions[i]);
            const float h = 1f / 60f;
            double Residual(int newton, out int cg)
            {
                FemModel model = data.AsModel();
                var v = new float3[n];
                var rotations = new quaternion[e];
                Array.Fill(rotations, quaternion.identity);
                var tangents = new float3[NeoHookeanTangent.Float3Count * e];
                var slots = new float3[4 * e];
                var scratch = new float3[n];
                var work = new float3[FemState.WorkVectors * n];
                cg = FemImplicitEuler.Solve(model, FemMaterialModel.NeoHookean, x0, v, rotations, tangents, 20, slots, scratch, work, default,
                    default, h, 0f, newton, 2000, 1e-7f, out bool converged, out _, out _);
                Assert.That(converged);
                var x1 = new float3[n];
                for (int i = 0; i < n; i++)
                    x1[i] = x0[i] + h * v[i];
                FemForces.Elastic(model, FemMaterialModel.NeoHookean, x1, default, 0f, rotations, 20, slots, 0, e);
                var f = new float3[n];
                FemForces.Gather(model, slots, f, 0, n);
                double rr = 0;
                for (int i = 0; i < n; i++)
                    rr += math.lengthsq(model.Masses[i] * v[i] - h * f[i]);
                return Math.Sqrt(rr);
            }
            // Scale: h f(x₀), the residual of v⁺ = 0.
            var forces0 = new float3[n];
            {
                FemModel model = data.AsModel();
                var rotations = new quaternion[e];
                var slots = new float3[4 * e];
                FemForces.Elastic(model, FemMaterialModel.NeoHookean, x0, default, 0f, rotations, 20, slots, 0, e);
                FemForces.Gather(model, slots, forces0, 0, n);
            }
            double scale = 0;
            foreach (float3 fi in forces0)
                scale += math.lengthsq(h * fi);
            scale = Math.Sqrt(scale);
            double previous = scale;
            foreach (int newton in new[] { 1, 2, 4 })
            {
                double residual = Residual(newton, out int cg);
                TestContext.WriteLine($"{newton} Newton iterations ({cg} CG): residual {residual / scale:G3} of |h f(x₀)|");
                Assert.That(residual, Is.LessThan(0.5 * previous), "each doubling of the iterations at least halves the residual");
                previous = residual;
            }
            // CG to 1e-7 per solve and float32 forces (~1e-6 of |f|): 4 iterations reach well below 1e-3.
            Assert.That(previous, Is.LessThan(1e-3 * scale));
        }
    }
}
