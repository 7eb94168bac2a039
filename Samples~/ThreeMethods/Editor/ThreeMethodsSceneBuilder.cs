using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Editor;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace SoftBodyDynamics.Samples.ThreeMethods
{
    /// <summary>
    /// Builds the "Three methods" sample next to this script: a main scene (camera, light, one SubScene) and the
    /// SubScene it loads (a floor plane and the same jelly cube three times side by side, simulated by shape matching,
    /// mass-spring and FEM, all with the Jelly preset), plus four materials made from the active render pipeline's
    /// default material and a readable copy of Unity's cube mesh (a soft body deforms its own copy of its mesh at run
    /// time, which needs Read/Write). Menu: Tools ▸ Soft Body Dynamics ▸ Samples ▸ Build Three Methods Scene.
    /// </summary>
    static class ThreeMethodsSceneBuilder
    {
        const string k_MenuPath = "Tools/Soft Body Dynamics/Samples/Build Three Methods Scene";
        const string k_ScriptName = nameof(ThreeMethodsSceneBuilder);
        const string k_MainSceneName = "ThreeMethods";
        const string k_SubSceneName = "ThreeMethods_SubScene";

        /// <summary>Height (m) the three cubes are dropped from, and the distance between them (m).</summary>
        const float k_DropHeight = 2.5f;
        const float k_Spacing = 2f;

        [MenuItem(k_MenuPath)]
        static void Build()
        {
            if (!SampleSceneBuilder.TryBegin("Three Methods sample", k_ScriptName, "ThreeMethods", k_MainSceneName, k_SubSceneName,
                    out SampleScenePaths paths, out Material template))
                return;

            string materialFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Materials");
            Material shapeMatching = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/ShapeMatching.mat", new Color(0.35f, 0.85f, 0.4f));
            Material massSpring = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/MassSpring.mat", new Color(0.95f, 0.6f, 0.2f));
            Material fem = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Fem.mat", new Color(0.3f, 0.55f, 0.95f));
            Material floor = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Floor.mat", new Color(0.32f, 0.33f, 0.36f));

            // A new main scene first: the temporary primitive the mesh copy is read from lives in it.
            Scene main = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            string meshFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Meshes");
            Mesh cube = SampleSceneBuilder.CreateReadableCopy(PrimitiveType.Cube, $"{meshFolder}/SoftCube.asset");
            AssetDatabase.SaveAssets();

            SampleSceneBuilder.AddCamera(main, new Vector3(0f, 2.5f, -8f), Quaternion.Euler(10f, 0f, 0f));
            SampleSceneBuilder.AddLight(main);

            // The same cube, the same Jelly preset (one physical material), the same drop: only the method differs.
            Scene sub = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Additive);
            SampleSceneBuilder.AddFloor(sub, floor, Vector3.zero);
            Quaternion tilt = Quaternion.Euler(20f, 0f, 15f);
            AddSoftBody(sub, "Jelly Cube (Shape Matching)", cube, SoftBodyMethod.ShapeMatching, shapeMatching, new Vector3(-k_Spacing, k_DropHeight, 0f), tilt);
            AddSoftBody(sub, "Jelly Cube (Mass Spring)", cube, SoftBodyMethod.MassSpring, massSpring, new Vector3(0f, k_DropHeight, 0f), tilt);
            AddSoftBody(sub, "Jelly Cube (FEM)", cube, SoftBodyMethod.Fem, fem, new Vector3(k_Spacing, k_DropHeight, 0f), tilt);
            SampleSceneBuilder.SaveWithSubScene(main, sub, paths);
            Debug.Log($"Three Methods sample built: {paths.MainScene} (open) and {paths.SubScene}. Press Play to drop the three cubes.");
        }

        static void AddSoftBody(Scene scene, string name, Mesh mesh, SoftBodyMethod method, Material material, Vector3 position,
            Quaternion rotation)
        {
            GameObject body = SampleSceneBuilder.CreateVisual(name, PrimitiveType.Cube, material, scene);
            body.GetComponent<MeshFilter>().sharedMesh = mesh;
            body.transform.position = position;
            body.transform.rotation = rotation;
            SoftBodyAuthoring softBody = body.AddComponent<SoftBodyAuthoring>();
            softBody.method = method;
            softBody.ApplyPreset(SoftBodyPreset.Jelly);
            // Shape matching: overlapping clusters of half the cube and interior particles every 0.2 m. Its total mass
            // is set by hand (the Jelly material's 1000 kg/m³ times 1 m³); the other methods take it from the density.
            softBody.totalMass = 1000f;
            softBody.clusterSize = 0.5f;
            softBody.addInteriorParticles = true;
            softBody.interiorSpacing = 0.2f;
            // Mass-spring and FEM: 6 cells along the side (216 cells, 1296 tetrahedra, 343 nodes).
            softBody.tetResolution = 6;
        }
    }
}
