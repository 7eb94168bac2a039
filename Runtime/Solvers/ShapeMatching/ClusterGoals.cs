using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The "solve" part of a substep: every cluster matches its rest shape to the predicted positions
    /// and each particle's goal is the average of its clusters' goals (lattice shape matching, Rivers
    /// &amp; James 2007, with weights wᵢ = mᵢ/nᵢ so that Σᵢ mᵢ(gᵢ − xᵢ) = 0 and momentum is conserved).
    /// </summary>
    public static class ClusterGoals
    {
        /// <summary>Fallbacks, rotation iterations and plastic updates of one pass.</summary>
        public struct Counters
        {
            public int Fallbacks;
            public int MaxIterations;
            public int PlasticUpdates;
            /// <summary>Plasticity was asked for in quadratic mode without per-instance quadratic inverses, so it did not flow.</summary>
            public bool PlasticityUnavailable;
        }

        /// <summary>
        /// Writes the averaged goal of every particle into <c>state.Goals</c> from the positions <paramref name="x"/>
        /// (particles in no cluster get their own position). When <paramref name="plasticStep"/> &gt; 0
        /// the clusters also flow plastically over that time (s): only in the linear and quadratic modes, whose
        /// goals can hold a deformed rest shape (rigid goals cannot deform, so nothing there may flow), and in
        /// quadratic mode only when the state has its own quadratic inverses to rewrite
        /// (<see cref="Counters.PlasticityUnavailable"/> otherwise: the body stays elastic rather than falling back to linear goals).
        /// </summary>
        public static Counters Compute(in ShapeMatchingModel model, in ShapeMatchingParameters p, in ShapeMatchingState state,
            System.ReadOnlySpan<float3> x, float plasticStep)
        {
            var counters = new Counters();
            var goals = state.Goals;
            for (int i = 0; i < goals.Length; i++)
                goals[i] = model.InverseClusterCounts[i] > 0f ? float3.zero : x[i];
            bool quadraticReady = model.HasQuadratic;
            var quadraticInverse = state.QuadraticInverse.Length == model.QuadraticInverse.Length
                ? state.QuadraticInverse : default;
            bool plasticWanted = p.Plasticity.Enabled && p.Mode != ShapeMatchingMode.Rigid;
            if (plasticWanted && p.Mode == ShapeMatchingMode.Quadratic && quadraticReady && quadraticInverse.Length == 0)
            {
                counters.PlasticityUnavailable = true;
                plasticWanted = false;
            }
            bool plastic = plasticStep > 0f && plasticWanted;
            for (int c = 0; c < model.ClusterCount; c++)
            {
                ref ClusterState cluster = ref state.Clusters[c];
                int start = model.ClusterOffsets[c], end = model.ClusterOffsets[c + 1];
                float totalMass = cluster.Rest.TotalMass;
                if (!(totalMass > 0f))
                    continue;
                // Eq. 4/5: weighted centre of the predicted positions.
                float3 sum = float3.zero;
                for (int k = start; k < end; k++)
                    sum += model.ClusterWeights[k] * x[model.ClusterParticles[k]];
                float3 center = sum / totalMass;
                // Rest offsets are Sₚ qᵢ once the cluster has flowed (§4.5); skip the product while Sₚ = I.
                float3x3 sp = cluster.PlasticDeformation;
                bool usePlastic = !IsIdentity(sp);

                bool quadratic = p.Mode == ShapeMatchingMode.Quadratic && quadraticReady && cluster.Rest.QuadraticValid
                                 && (!usePlastic || quadraticInverse.Length > 0);
                if (p.Mode == ShapeMatchingMode.Quadratic && !quadratic)
                    counters.Fallbacks++;

                // Plastic flow needs R and A = A_pq A_qq⁻¹ of this substep.
                float3x3 aLinear, r;
                if (quadratic)
                {
                    QuadraticGoals(model, p, state, x, c, start, end, center, sp, usePlastic, ref cluster, quadraticInverse.Length > 0
                        ? quadraticInverse.Slice(c * QuadraticShapeMatching.BlocksPerCluster, QuadraticShapeMatching.BlocksPerCluster)
                        : model.QuadraticInverse.Slice(c * QuadraticShapeMatching.BlocksPerCluster, QuadraticShapeMatching.BlocksPerCluster),
                        ref counters, out aLinear, out r);
                }
                else
                {
                    // Eq. 7: A_pq = Σ wᵢ pᵢ qᵢᵀ with qᵢ = Sₚ (x⁰ᵢ − x⁰_cm).
                    float3x3 apq = float3x3.zero;
                    for (int k = start; k < end; k++)
                    {
                        int i = model.ClusterParticles[k];
                        float3 q = RestOffset(model.RestPositions[i], cluster.Rest.RestCenter, sp, usePlastic);
                        apq += model.ClusterWeights[k] * Matrix3.Outer(x[i] - center, q);
                    }
                    // A quadratic body whose cluster fell back uses the linear mode here.
                    var mode = p.Mode == ShapeMatchingMode.Rigid ? ShapeMatchingMode.Rigid : ShapeMatchingMode.Linear;
                    float3x3 t = ShapeMatching.GoalTransform(apq, cluster.Rest, mode, p.Beta, ref cluster.Rotation,
                        p.RotationIterations, out int iterations, out bool fallback);
                    counters.MaxIterations = math.max(counters.MaxIterations, iterations);
                    if (fallback && p.Mode == ShapeMatchingMode.Linear)
                        counters.Fallbacks++;
                    r = new float3x3(cluster.Rotation);
                    aLinear = plastic && cluster.Rest.LinearValid ? math.mul(apq, cluster.Rest.AqqInverse) : r;
                    // Eq. 9: gᵢ = T qᵢ + x_cm, averaged over the clusters of particle i.
                    if (usePlastic)
                        t = math.mul(t, sp);
                    for (int k = start; k < end; k++)
                    {
                        int i = model.ClusterParticles[k];
                        goals[i] += model.InverseClusterCounts[i] * (math.mul(t, model.RestPositions[i] - cluster.Rest.RestCenter) + center);
                    }
                }

                if (plastic && cluster.Rest.LinearValid && model.ClusterRest[c].LinearValid
                    && Plasticity.Update(ref cluster, aLinear, r, model.ClusterRest[c].AqqInverse, p.Plasticity, plasticStep))
                {
                    counters.PlasticUpdates++;
                    if (quadratic && quadraticInverse.Length > 0)
                    {
                        var blocks = quadraticInverse.Slice(c * QuadraticShapeMatching.BlocksPerCluster, QuadraticShapeMatching.BlocksPerCluster);
                        cluster.Rest.QuadraticValid = QuadraticShapeMatching.ComputeRestInverse(model.RestPositions,
                            model.ClusterParticles.Slice(start, end - start), model.ClusterWeights.Slice(start, end - start),
                            cluster.Rest.RestCenter, cluster.PlasticDeformation, cluster.Rest.LengthScale, blocks, out _,
                            out cluster.Rest.QuadraticMeanSquare, out cluster.Rest.QuadraticMeanCross);
                    }
                }
            }
            return counters;
        }

        /// <summary>Largest ratio of the squared RMS strain to the squared RMS displacement (over L) of a quadratic deformation in a uniformly filled cluster.</summary>
        const float k_QuadraticStrainPerDisplacement = 15f;

        /// <summary>Eq. 11/12 in coordinates scaled by 1/L, with the centred q̃: gᵢ = x_cm + L (β Ã + (1 − β)[R 0 0]) q̃ᵢ.</summary>
        static void QuadraticGoals(in ShapeMatchingModel model, in ShapeMatchingParameters p, in ShapeMatchingState state,
            System.ReadOnlySpan<float3> x, int c, int start, int end, float3 center, in float3x3 sp, bool usePlastic, ref ClusterState cluster,
            System.ReadOnlySpan<float3x3> inverseBlocks, ref Counters counters, out float3x3 aLinear, out float3x3 r)
        {
            float length = cluster.Rest.LengthScale;
            float invL = 1f / length;
            float3x3 p0 = float3x3.zero, p1 = float3x3.zero, p2 = float3x3.zero;
            float restSpread = 0f; // tr(A_qq) of the scaled linear part, Σ wᵢ |qᵢ/L|²
            for (int k = start; k < end; k++)
            {
                int i = model.ClusterParticles[k];
                float3 q = RestOffset(model.RestPositions[i], cluster.Rest.RestCenter, sp, usePlastic);
                QuadraticShapeMatching.Lift(q * invL, cluster.Rest, out float3 a, out float3 b, out float3 cr);
                float3 wp = model.ClusterWeights[k] * invL * (x[i] - center);
                p0 += Matrix3.Outer(wp, a);
                p1 += Matrix3.Outer(wp, b);
                p2 += Matrix3.Outer(wp, cr);
                restSpread += model.ClusterWeights[k] * math.lengthsq(a);
            }
            // p0 is A_pq / L²: same rotation.
            int iterations = RotationExtraction.Extract(p0, ref cluster.Rotation, p.RotationIterations);
            counters.MaxIterations = math.max(counters.MaxIterations, iterations);
            r = new float3x3(cluster.Rotation);
            aLinear = cluster.Rest.LinearValid ? math.mul(p0, cluster.Rest.AqqInverse) * (length * length) : r;
            QuadraticShapeMatching.Transform(p0, p1, p2, inverseBlocks, out float3x3 t0, out float3x3 t1, out float3x3 t2);
            // A flat, collapsed or inverted linear block (det Ã₀ at or below the linear mode's floor) must not be
            // followed: the β part fades out toward the floor and the goals become rigid, as in the linear mode.
            const float floor = VolumePreservation.DefaultRelativeDeterminantFloor;
            float relativeDeterminant = VolumePreservation.RelativeDeterminant(t0);
            float fade = VolumePreservation.BetaFade(relativeDeterminant);
            if (fade < 1f)
                counters.Fallbacks++;
            // β blend toward Ã, with the strain limited so that the pull stays an energy's gradient (VolumePreservation.StrainLimit),
            // in two levels: the fit energies E_R ≥ E_A ≥ E_Ã (rotation, linear fit A, quadratic fit Ã) give the goal transform
            // R + c₁ (A − R) + c₂ (Ã − A), the gradient of Φ = E_R − h₁(E_R − E_A) − h₂(E_A − E_Ã) with cₖ = hₖ′. The linear level
            // is limited as in the linear mode; the quadratic surplus by its strain, whose RMS is at most √15 times its RMS
            // displacement in a uniformly filled cluster (u = C(x² − ⟨x²⟩): 4⟨x²⟩/(⟨x⁴⟩ − ⟨x²⟩²) = 15 at ⟨x²⟩ = 1/3, ⟨x⁴⟩ = 1/5).
            // 2(E_R − E_A) = ⟨A, Ã_pq,₀⟩ − 2⟨R, Ã_pq,₀⟩ + tr(A_qq), 2(E_A − E_Ã) = Σⱼ ⟨Ãⱼ, Ã_pq,ⱼ⟩ − ⟨A, Ã_pq,₀⟩ (scaled by 1/L).
            float weight = fade * math.saturate(p.Beta);
            float linearFit = Matrix3.Dot(aLinear, p0);
            float linearGap = linearFit - 2f * Matrix3.Dot(r, p0) + restSpread;
            float quadraticGap = Matrix3.Dot(t0, p0) + Matrix3.Dot(t1, p1) + Matrix3.Dot(t2, p2) - linearFit;
            float c1 = weight * VolumePreservation.StrainLimit(linearGap, cluster.Rest.TotalMass);
            float c2 = weight * VolumePreservation.StrainLimit(k_QuadraticStrainPerDisplacement * quadraticGap, cluster.Rest.TotalMass);
            float3x3 g0 = r + c1 * (aLinear - r) + c2 * (t0 - aLinear), g1 = c2 * t1, g2 = c2 * t2;
            // Volume: the β part follows a change of volume too, so the goals add the gradient of a volume energy,
            // E = ½ ω² κ M L² (J − 1)² with J = det A, A = A_pq A_qq⁻¹ of the linear fit: ∂J/∂xᵢ = wᵢ cof(A) A_qq⁻¹ qᵢ, so the
            // goal of particle i moves by −κ (J − 1) cof(A) (M L² A_qq⁻¹) qᵢ. With κ = β/9 a small uniform dilation of an
            // isotropic cluster (M L² A_qq⁻¹ = 3·I) is resisted at the full ω², as in the linear mode, and J is exact at
            // any strain. An energy's gradient keeps the pull conservative, so an undamped body gains no energy (the
            // linear mode's A / ∛det A applied to the 9-D fit's coupled linear block does not, and makes undamped
            // small clusters grow).
            float3x3 volumePull = float3x3.zero;
            if (cluster.Rest.LinearValid && relativeDeterminant > floor)
            {
                float j = math.determinant(aLinear);
                float3x3 cofactor = j * math.transpose(math.inverse(aLinear));
                float kappa = fade * math.saturate(p.Beta) / 9f;
                volumePull = (-kappa * (j - 1f) * cluster.Rest.TotalMass * length * length)
                             * math.mul(cofactor, cluster.Rest.AqqInverse);
                if (!Finite.All(volumePull))
                    volumePull = float3x3.zero;
            }
            var goals = state.Goals;
            for (int k = start; k < end; k++)
            {
                int i = model.ClusterParticles[k];
                float3 q = RestOffset(model.RestPositions[i], cluster.Rest.RestCenter, sp, usePlastic);
                QuadraticShapeMatching.Lift(q * invL, cluster.Rest, out float3 a, out float3 b, out float3 cr);
                float3 g = center + length * (math.mul(g0, a) + math.mul(g1, b) + math.mul(g2, cr)) + math.mul(volumePull, q);
                goals[i] += model.InverseClusterCounts[i] * g;
            }
        }

        /// <summary>qᵢ = Sₚ (x⁰ᵢ − x⁰_cm), skipping the product while the cluster has not flowed (Sₚ = I).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        static float3 RestOffset(float3 rest, float3 restCenter, in float3x3 sp, bool usePlastic) =>
            usePlastic ? math.mul(sp, rest - restCenter) : rest - restCenter;

        static bool IsIdentity(in float3x3 m) =>
            m.c0.x == 1f && m.c1.y == 1f && m.c2.z == 1f && m.c0.y == 0f && m.c0.z == 0f
            && m.c1.x == 0f && m.c1.z == 0f && m.c2.x == 0f && m.c2.y == 0f;
    }
}
