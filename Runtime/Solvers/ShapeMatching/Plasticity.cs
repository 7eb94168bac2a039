using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Plastic flow of a cluster's rest shape (Müller et al. 2005, §4.5). With A = A_pq A_qq⁻¹ = R S
    /// the deformation relative to the current rest shape is S = Rᵀ A. While ‖S − I‖_F exceeds the
    /// yield, Sₚ ← sym((I + h·creep·(S − I)) Sₚ); then ‖Sₚ − I‖_F is clamped to the maximum deformation (once there,
    /// it flows no further) and
    /// Sₚ is divided by ∛det Sₚ so plastic flow keeps the volume. Rest offsets become Sₚ qᵢ, hence
    /// A_qq' = Sₚ A_qq Sₚᵀ and A_qq'⁻¹ = Sₚ⁻ᵀ A_qq⁻¹ Sₚ⁻¹.
    /// </summary>
    public static class Plasticity
    {
        /// <summary>
        /// Updates <paramref name="cluster"/>'s Sₚ and A_qq⁻¹ from the linear transform of this substep.
        /// Returns true when the rest shape changed. Leaves the cluster untouched for degenerate input.
        /// </summary>
        /// <param name="aLinear">A = A_pq A_qq⁻¹ of the current (plastic) rest shape.</param>
        /// <param name="rotation">R, the rotational part of A_pq.</param>
        /// <param name="originalAqqInverse">A_qq⁻¹ of the model's undeformed rest shape.</param>
        /// <param name="h">Time step (s).</param>
        public static bool Update(ref ClusterState cluster, in float3x3 aLinear, in float3x3 rotation,
            in float3x3 originalAqqInverse, in PlasticityParameters parameters, float h)
        {
            float3x3 s = math.mul(math.transpose(rotation), aLinear);
            // The polar factor of a proper rotation makes S symmetric; average out float round-off.
            s = 0.5f * (s + math.transpose(s));
            float3x3 strain = s - float3x3.identity;
            float strainNorm = FrobeniusNorm(strain);
            if (!(strainNorm > parameters.Yield) || !math.isfinite(strainNorm))
                return false;
            float3x3 sp = math.mul(float3x3.identity + (h * parameters.Creep) * strain, cluster.PlasticDeformation);
            // The product of two symmetric matrices is not symmetric: its antisymmetric part would rotate the rest
            // shape a little at every update, and rest shapes that turn in overlapping clusters roll the body across
            // the floor. Plastic flow is a stretch of the rest shape, so only the symmetric part is kept.
            sp = 0.5f * (sp + math.transpose(sp));
            float3x3 excess = sp - float3x3.identity;
            float excessNorm = FrobeniusNorm(excess);
            if (excessNorm > parameters.MaxDeformation)
            {
                // At the bound the material has hardened: flow that would take it further is refused. Scaling it back
                // onto the bound instead lets Sₚ slide along the bound forever while the load keeps the strain above
                // the yield, and a rest shape that never stops changing walks the body across the floor.
                if (FrobeniusNorm(cluster.PlasticDeformation - float3x3.identity) >= parameters.MaxDeformation * 0.999f)
                    return false;
                sp = float3x3.identity + excess * (parameters.MaxDeformation / excessNorm);
            }
            float det = math.determinant(sp);
            if (!(det > 1e-6f) || !Finite.All(sp))
                return false;
            sp *= 1f / math.pow(det, 1f / 3f);
            float3x3 spInverse = math.inverse(sp);
            cluster.PlasticDeformation = sp;
            cluster.Rest.AqqInverse = math.mul(math.transpose(spInverse), math.mul(originalAqqInverse, spInverse));
            return true;
        }

        /// <summary>‖M‖_F.</summary>
        public static float FrobeniusNorm(in float3x3 m) =>
            math.sqrt(math.lengthsq(m.c0) + math.lengthsq(m.c1) + math.lengthsq(m.c2));
    }
}
