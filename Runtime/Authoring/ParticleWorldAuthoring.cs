using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// World-level soft-body settings: one per world (put it on one GameObject of a SubScene). Baked into the
    /// <see cref="ParticleWorldSettings"/> singleton; every soft body then uses this gravity and at least these substeps.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Particle World")]
    public sealed class ParticleWorldAuthoring : MonoBehaviour
    {
        [Tooltip("Acceleration of gravity for every soft body (m/s²). It replaces each body's own Gravity. Default (0, −9.81, 0).")]
        public Vector3 gravity = UnityMathConversions.ToVector3(ParticleWorldSettings.Default.Gravity);

        [Tooltip("Fewest substeps per fixed step for every soft body (1–64); a body's own Substeps applies if larger. Default 1.")]
        [Range(1, 64)]
        public int minSubsteps = ParticleWorldSettings.Default.MinSubsteps;

        /// <summary>True when <see cref="gravity"/> is finite.</summary>
        public bool GravityIsFinite => math.all(math.isfinite(UnityMathConversions.ToFloat3(gravity)));

        /// <summary>The singleton's value, with the substeps clamped to 1–64 and a non-finite gravity replaced by the default.</summary>
        public ParticleWorldSettings Settings => new ParticleWorldSettings
        {
            Gravity = GravityIsFinite ? UnityMathConversions.ToFloat3(gravity) : ParticleWorldSettings.Default.Gravity,
            MinSubsteps = math.clamp(minSubsteps, 1, 64),
        };
    }

    /// <summary>Bakes <see cref="ParticleWorldAuthoring"/> into the <see cref="ParticleWorldSettings"/> singleton.</summary>
    public sealed class ParticleWorldBaker : Baker<ParticleWorldAuthoring>
    {
        public override void Bake(ParticleWorldAuthoring authoring)
        {
            if (!authoring.GravityIsFinite)
                Debug.LogError($"Particle World on '{authoring.name}': Gravity is not finite; the default (0, −9.81, 0) is used.", authoring);
            Entity entity = GetEntity(TransformUsageFlags.None);
            AddComponent(entity, authoring.Settings);
        }
    }
}
