using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Editor;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace SoftBodyDynamics.Samples.JellyAndSphere
{
    /// <summary>
    /// Builds the "Jelly and sphere" sample next to this script: a main scene (camera, light, one SubScene) and
    /// the SubScene it loads (floor plane, four box steps, three jelly cubes and a rubber sphere), plus four
    /// materials made from the active render pipeline's default material and readable copies of Unity's cube and
    /// sphere meshes (a soft body deforms its own copy of its mesh at run time, which needs Read/Write).
    /// Menu: Tools ▸ Soft Body Dynamics ▸ Samples ▸ Build Jelly and Sphere Scene.
    /// </summary>
    static class JellyAndSphereSceneBuilder
    {
        const string k_MenuPath = "Tools/Soft Body Dynamics/Samples/Build Jelly and Sphere Scene";
        const string k_ScriptName = nameof(JellyAndSphereSceneBuilder);
        const string k_MainSceneName = "JellyAndSphere";
        const string k_SubSceneName = "JellyAndSphere_SubScene";

        /// <summary>Steps of the staircase, high to low, 1.5 m deep each (centre x, height; m).</summary>
        static readonly (float X, float Height)[] k_Steps = { (0f, 2f), (1.5f, 1.5f), (3f, 1f), (4.5f, 0.5f) };
        const float k_StepDepth = 1.5f;
        const float k_StepWidth = 3f;

        [MenuItem(k_MenuPath)]
        static void Build()
        {
            if (!SampleSceneBuilder.TryBegin("Jelly and Sphere sample", k_ScriptName, "JellyAndSphere", k_MainSceneName, k_SubSceneName,
                    out SampleScenePaths paths, out Material template))
                return;

            string materialFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Materials");
            Material jelly = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Jelly.mat", new Color(0.35f, 0.85f, 0.4f));
            Material rubber = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Rubber.mat", new Color(0.95f, 0.35f, 0.2f));
            Material steps = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Steps.mat", new Color(0.62f, 0.62f, 0.68f));
            Material floor = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Floor.mat", new Color(0.32f, 0.33f, 0.36f));

            // A new main scene first: the temporary primitives the mesh copies are read from live in it.
            Scene main = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            string meshFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Meshes");
            Mesh cube = SampleSceneBuilder.CreateReadableCopy(PrimitiveType.Cube, $"{meshFolder}/SoftCube.asset");
            Mesh sphere = SampleSceneBuilder.CreateReadableCopy(PrimitiveType.Sphere, $"{meshFolder}/SoftSphere.asset");
            AssetDatabase.SaveAssets();

            SampleSceneBuilder.AddCamera(main, new Vector3(2.25f, 4.5f, -10f), Quaternion.Euler(14f, 0f, 0f));
            SampleSceneBuilder.AddLight(main);

            Scene sub = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Additive);
            SampleSceneBuilder.AddFloor(sub, floor, new Vector3(2.25f, 0f, 0f));
            AddSteps(sub, steps);
            AddSoftBody(sub, "Jelly Cube A", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(0.6f, 4f, -0.7f), Quaternion.identity);
            AddSoftBody(sub, "Jelly Cube B", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(2.1f, 5.5f, 0.6f), Quaternion.Euler(0f, 20f, 10f));
            AddSoftBody(sub, "Jelly Cube C", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(-0.2f, 7f, 0.2f), Quaternion.Euler(15f, 30f, 0f));
            AddSoftBody(sub, "Rubber Sphere", sphere, SoftBodyPreset.Rubber, 0.5f, rubber, new Vector3(3.6f, 6f, -0.5f), Quaternion.identity);
            SampleSceneBuilder.SaveWithSubScene(main, sub, paths);
            Debug.Log($"Jelly and Sphere sample built: {paths.MainScene} (open) and {paths.SubScene}. Press Play to drop the bodies onto the steps.");
        }

        static void AddSteps(Scene scene, Material material)
        {
            for (int i = 0; i < k_Steps.Length; i++)
            {
                (float x, float height) = k_Steps[i];
                GameObject step = SampleSceneBuilder.CreateVisual($"Step {i + 1}", PrimitiveType.Cube, material, scene);
                step.transform.position = new Vector3(x, 0.5f * height, 0f);
                step.transform.localScale = new Vector3(k_StepDepth, height, k_StepWidth);
                // The default box (1 m cube at the centre) matches the cube mesh; the Transform's scale sizes both.
                step.AddComponent<ParticleColliderAuthoring>().shape = ColliderShapeType.Box;
            }
        }

        static void AddSoftBody(Scene scene, string name, Mesh mesh, SoftBodyPreset preset, float mass, Material material,
            Vector3 position, Quaternion rotation)
        {
            GameObject body = SampleSceneBuilder.CreateVisual(name, PrimitiveType.Cube, material, scene);
            body.GetComponent<MeshFilter>().sharedMesh = mesh;
            body.transform.position = position;
            body.transform.rotation = rotation;
            SoftBodyAuthoring softBody = body.AddComponent<SoftBodyAuthoring>();
            softBody.ApplyPreset(preset);
            softBody.clusterSize = 0.5f;
            softBody.addInteriorParticles = true;
            softBody.interiorSpacing = 0.2f;
            softBody.totalMass = mass;
        }
    }
}
