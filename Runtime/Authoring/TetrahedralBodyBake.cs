using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// The components of a baked mass-spring or FEM body (the baker and the tests share this one code path; the simulation
    /// components come from <see cref="SoftBodyArchetype.WriteMassSpring"/> / <see cref="SoftBodyArchetype.WriteFem"/>,
    /// as for bodies made from code):
    /// <list type="bullet">
    /// <item>tier 1: the method's shape blob (<see cref="MassSpringShape"/> or <see cref="FemShape"/>) and the render
    /// embedding (<see cref="SoftBodyEmbedding"/>);</item>
    /// <item>tier 2: the solver parameters (<see cref="MassSpringSettings"/> or <see cref="FemSettings"/>);</item>
    /// <item>tier 3: <see cref="ParticleBodyState"/>, the <see cref="SoftBodyPosition"/> and <see cref="SoftBodyVelocity"/>
    /// buffers (FEM: <see cref="FemElementRotation"/> and <see cref="FemDiagnostics"/>), <see cref="SoftBodyUninitialized"/>
    /// enabled and <see cref="SoftBodyImpulse"/> disabled;</item>
    /// <item><see cref="SoftBodyRenderMesh"/> when there is a mesh to draw.</item>
    /// </list>
    /// </summary>
    public static class TetrahedralBodyBake
    {
        /// <summary>Writes the components of <paramref name="build"/>, which must have <see cref="SoftBodyAuthoringBuild.Succeeded"/>.</summary>
        /// <param name="authoring">The authoring component (parameters).</param>
        /// <param name="build">Its successful mass-spring or FEM build.</param>
        /// <param name="renderMesh">The mesh to draw deformed; null for none.</param>
        /// <param name="writer">Where the components go.</param>
        public static void Write(SoftBodyAuthoring authoring, SoftBodyAuthoringBuild build, Mesh renderMesh, ISoftBodyEntityWriter writer)
        {
            if (build == null || !build.Succeeded || build.Tetrahedral == null)
                throw new ArgumentException("Only a successful mass-spring or FEM build can be baked.", nameof(build));
            TetrahedralBodyBuild body = build.Tetrahedral;
            if (body.Method == SoftBodyMethod.MassSpring)
            {
                BlobAssetReference<MassSpringShapeBlob> shape = MassSpringShapeBlobFactory.Create(body.MassSpring.AsModel(), Allocator.Persistent);
                writer.AddBlob(ref shape);
                SoftBodyArchetype.WriteMassSpring(writer, shape, authoring.MassSpringParameters);
                AddEmbedding(build, body.MassSpring.RestPositions, body.MassSpring.RestCenter, writer);
            }
            else
            {
                BlobAssetReference<FemShapeBlob> shape = FemShapeBlobFactory.Create(body.Fem.AsModel(), Allocator.Persistent);
                writer.AddBlob(ref shape);
                SoftBodyArchetype.WriteFem(writer, shape, authoring.FemParameters);
                AddEmbedding(build, body.Fem.RestPositions, body.Fem.RestCenter, writer, body.Fem.Order == FemElementOrder.Quadratic
                    ? QuadraticTetrahedra.EmbeddingEdgeNodes(build.Tetrahedral.Tetrahedralization.Embedding, body.NodeCount, body.Fem.EdgeEnds)
                    : null);
            }
            if (renderMesh != null)
                writer.AddComponent(new SoftBodyRenderMesh { Mesh = renderMesh });
        }

        static void AddEmbedding(SoftBodyAuthoringBuild build, Unity.Mathematics.float3[] restNodes, Unity.Mathematics.float3 restCenter,
            ISoftBodyEntityWriter writer, int[] edgeNodes = null)
        {
            BlobAssetReference<SoftBodyEmbeddingBlob> embedding = SoftBodyEmbeddingBlobFactory.Create(
                build.Tetrahedral.Tetrahedralization.Embedding, build.Mesh.Normals, restNodes, restCenter, Allocator.Persistent, edgeNodes);
            writer.AddBlob(ref embedding);
            writer.AddComponent(new SoftBodyEmbedding { Blob = embedding });
        }
    }
}
