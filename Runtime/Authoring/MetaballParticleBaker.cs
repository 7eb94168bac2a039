using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>Bakes a <see cref="MetaballParticleAuthoring"/> prefab: a movable entity with <see cref="FluidParticle"/> (filled in at spawn) and <see cref="MetaballParticle"/>.</summary>
    public sealed class MetaballParticleBaker : Baker<MetaballParticleAuthoring>
    {
        public override void Bake(MetaballParticleAuthoring authoring)
        {
            if (!(authoring.radius > 0f) || float.IsInfinity(authoring.radius))
                Debug.LogWarning($"Metaball Particle on '{authoring.name}': the radius must be a positive length (is {authoring.radius}); using 0.01 m.", authoring);
            Entity entity = GetEntity(TransformUsageFlags.Dynamic);
            AddComponent(entity, new FluidParticle());
            AddComponent(entity, new MetaballParticle { Radius = authoring.radius > 0f && !float.IsInfinity(authoring.radius) ? authoring.radius : 0.01f });
        }
    }
}
