using Unity.Collections;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// What reads the collider world: a particle body of any method or a fluid. The systems that build it
    /// (<see cref="ColliderWorldSystem"/>, and any system that adds colliders to it, such as the Unity Physics bridge)
    /// update only while one of these exists.
    /// </summary>
    public static class ColliderWorldReaders
    {
        /// <summary>Makes the system of <paramref name="state"/> update only while a reader exists (Burst-compatible: no managed array).</summary>
        public static void Require(ref SystemState state)
        {
            var readers = new NativeArray<EntityQuery>(4, Allocator.Temp);
            readers[0] = Query<ShapeMatchingShape>(ref state);
            readers[1] = Query<MassSpringShape>(ref state);
            readers[2] = Query<FemShape>(ref state);
            readers[3] = Query<FluidSettings>(ref state);
            state.RequireAnyForUpdate(readers);
            readers.Dispose();
        }

        static EntityQuery Query<T>(ref SystemState state)
        {
            var builder = new EntityQueryBuilder(Allocator.Temp);
            EntityQuery query = builder.WithAll<T>().Build(ref state);
            builder.Dispose();
            return query;
        }
    }
}
