using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Uploads each CPU fluid with a <see cref="FluidSurface"/> for the renderer once per rendered frame: its live
    /// particles' positions and attributes from the fluid's buffers (packed storage, and Entities storage whose particles
    /// the simulation gathers there) into one GraphicsBuffer, grown by doubling, with the spheres' world bounds, registered
    /// in this world's <see cref="Sources"/>. GPU fluids register their own buffer there (<see cref="FluidComputeSystem"/>).
    /// Updates only while a fluid surface exists.
    /// </summary>
    [UpdateInGroup(typeof(PresentationSystemGroup))]
    public partial class FluidSurfaceSourceSystem : SystemBase
    {
        readonly Dictionary<Entity, FluidRenderSource> m_Uploads = new Dictionary<Entity, FluidRenderSource>();

        /// <summary>This world's renderer hand-off: every fluid of the world the renderer draws.</summary>
        public FluidRenderSources Sources { get; } = new FluidRenderSources();
        readonly List<Entity> m_Gone = new List<Entity>();
        EntityQuery m_Fluids;

        protected override void OnCreate()
        {
            RequireForUpdate<FluidSurface>();
            m_Fluids = SystemAPI.QueryBuilder().WithAll<FluidSettings, FluidRuntime, FluidSurface>().WithAll<FluidPosition, FluidAttribute>().WithNone<FluidOnGpu>().Build();
        }

        protected override void OnUpdate()
        {
            CompleteDependency();
            EntityManager m = EntityManager;
            ReleaseRemoved(m);
            NativeArray<Entity> fluids = m_Fluids.ToEntityArray(Allocator.Temp);
            foreach (Entity fluid in fluids)
            {
                FluidSurface surface = m.GetComponentData<FluidSurface>(fluid);
                int count = m.GetComponentData<FluidRuntime>(fluid).Status.Count;
                DynamicBuffer<FluidPosition> positions = m.GetBuffer<FluidPosition>(fluid, true);
                DynamicBuffer<FluidAttribute> attributes = m.GetBuffer<FluidAttribute>(fluid, true);
                count = math.min(count, math.min(positions.Length, attributes.Length));
                if (!m_Uploads.TryGetValue(fluid, out FluidRenderSource source))
                {
                    source = new FluidRenderSource();
                    m_Uploads[fluid] = source;
                }
                var packed = new NativeArray<float4>(math.max(count, 1), Allocator.Temp);
                Bounds bounds = Pack(positions.AsNativeArray(), attributes.AsNativeArray(), count, surface.ParticleRadius, packed);
                if (source.Particles == null || source.Particles.count < count)
                {
                    source.Particles?.Release();
                    source.Particles = new GraphicsBuffer(GraphicsBuffer.Target.Structured, GrownLength(count), 16);
                }
                if (count > 0)
                    source.Particles.SetData(packed, 0, 0, count);
                source.Count = count;
                source.WorldBounds = bounds;
                source.ParticleRadius = surface.ParticleRadius;
                source.Look = surface.Look;
                Sources.Set(fluid, source);
                packed.Dispose();
            }
            fluids.Dispose();
        }

        /// <summary>The buffer length for <paramref name="count"/> slots: a power of two, at least 64, so a growing fluid reallocates rarely.</summary>
        public static int GrownLength(int count)
        {
            int length = 64;
            while (length < count)
                length *= 2;
            return length;
        }

        /// <summary>Positions and attributes into float4s; returns the bounds of the spheres (empty at the origin when there are none).</summary>
        public static Bounds Pack(NativeArray<FluidPosition> positions, NativeArray<FluidAttribute> attributes, int count, float radius, NativeArray<float4> packed)
        {
            float3 lo = new float3(float.MaxValue), hi = new float3(float.MinValue);
            for (int i = 0; i < count; i++)
            {
                float3 p = positions[i].Value;
                packed[i] = new float4(p, attributes[i].Value);
                if (math.all(math.isfinite(p)))
                {
                    lo = math.min(lo, p);
                    hi = math.max(hi, p);
                }
            }
            if (math.any(lo > hi))
                return new Bounds(Vector3.zero, Vector3.zero);
            return FluidRenderSource.SphereBounds(lo, hi, radius);
        }

        void ReleaseRemoved(EntityManager m)
        {
            m_Gone.Clear();
            foreach (var pair in m_Uploads)
                if (!m.Exists(pair.Key) || !m.HasComponent<FluidSurface>(pair.Key) || m.HasComponent<FluidOnGpu>(pair.Key))
                    m_Gone.Add(pair.Key);
            foreach (Entity e in m_Gone)
            {
                m_Uploads[e].Particles?.Release();
                m_Uploads.Remove(e);
                if (Sources.Get(e) != null && !m.HasComponent<FluidOnGpu>(e))
                    Sources.Remove(e);
            }
        }

        protected override void OnDestroy()
        {
            foreach (var pair in m_Uploads)
            {
                pair.Value.Particles?.Release();
                Sources.Remove(pair.Key);
            }
            m_Uploads.Clear();
        }
    }
}
