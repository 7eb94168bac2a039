using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>Builds <see cref="MassSpringShapeBlob"/> assets from a mass-spring model (bake time, managed).</summary>
    public static class MassSpringShapeBlobFactory
    {
        /// <summary>
        /// Copies <paramref name="model"/> into a new blob asset. The caller owns the result: hand it to the baker
        /// (<c>AddBlobAsset</c>) or <c>Dispose</c> it.
        /// </summary>
        /// <param name="model">The model (<c>MassSpringModelData.AsModel()</c>).</param>
        /// <param name="allocator">Allocator of the blob (<see cref="Allocator.Persistent"/> for baking).</param>
        public static BlobAssetReference<MassSpringShapeBlob> Create(in MassSpringModel model, Allocator allocator)
        {
            var builder = new BlobBuilder(Allocator.Temp);
            try
            {
                ref MassSpringShapeBlob root = ref builder.ConstructRoot<MassSpringShapeBlob>();
                builder.Construct(ref root.RestPositions, model.RestPositions.ToArray());
                root.RestCenter = model.RestCenter;
                builder.Construct(ref root.Masses, model.Masses.ToArray());
                builder.Construct(ref root.InverseMasses, model.InverseMasses.ToArray());
                builder.Construct(ref root.Springs, model.Springs.ToArray());
                builder.Construct(ref root.IncidenceOffsets, model.IncidenceOffsets.ToArray());
                builder.Construct(ref root.IncidenceSlots, model.IncidenceSlots.ToArray());
                builder.Construct(ref root.ColorOffsets, model.ColorOffsets.ToArray());
                builder.Construct(ref root.ColorSprings, model.ColorSprings.ToArray());
                return builder.CreateBlobAssetReference<MassSpringShapeBlob>(allocator);
            }
            finally
            {
                builder.Dispose();
            }
        }
    }
}
