using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>Builds <see cref="FemShapeBlob"/> assets from a finite-element model (bake time, managed).</summary>
    public static class FemShapeBlobFactory
    {
        /// <summary>
        /// Copies <paramref name="model"/> into a new blob asset. The caller owns the result: hand it to the baker
        /// (<c>AddBlobAsset</c>) or <c>Dispose</c> it.
        /// </summary>
        /// <param name="model">The model (<c>FemModelData.AsModel()</c>).</param>
        /// <param name="allocator">Allocator of the blob (<see cref="Allocator.Persistent"/> for baking).</param>
        public static BlobAssetReference<FemShapeBlob> Create(in FemModel model, Allocator allocator)
        {
            var builder = new BlobBuilder(Allocator.Temp);
            try
            {
                ref FemShapeBlob root = ref builder.ConstructRoot<FemShapeBlob>();
                builder.Construct(ref root.RestPositions, model.RestPositions.ToArray());
                builder.Construct(ref root.Masses, model.Masses.ToArray());
                builder.Construct(ref root.InverseMasses, model.InverseMasses.ToArray());
                builder.Construct(ref root.Elements, model.Elements.ToArray());
                builder.Construct(ref root.IncidenceOffsets, model.IncidenceOffsets.ToArray());
                builder.Construct(ref root.IncidenceSlots, model.IncidenceSlots.ToArray());
                builder.Construct(ref root.ColorOffsets, model.ColorOffsets.ToArray());
                builder.Construct(ref root.ColorElements, model.ColorElements.ToArray());
                builder.Construct(ref root.StiffnessDiagonal, model.StiffnessDiagonal.ToArray());
                builder.Construct(ref root.ElementNodes, model.ElementNodes.ToArray());
                builder.Construct(ref root.PointGradients, model.PointGradients.ToArray());
                builder.Construct(ref root.PointVolumes, model.PointVolumes.ToArray());
                builder.Construct(ref root.FactorNodes, model.FactorNodes.ToArray());
                builder.Construct(ref root.FactorRowStarts, model.FactorRowStarts.ToArray());
                builder.Construct(ref root.FactorValues, model.FactorValues.ToArray());
                root.RestCenter = model.RestCenter;
                root.Mu = model.Mu;
                root.Lambda = model.Lambda;
                root.DampingRatio = model.DampingRatio;
                root.DefaultDampingFrequency = model.DefaultDampingFrequency;
                return builder.CreateBlobAssetReference<FemShapeBlob>(allocator);
            }
            finally
            {
                builder.Dispose();
            }
        }
    }
}
