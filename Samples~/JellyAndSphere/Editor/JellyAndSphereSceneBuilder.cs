using System.IO;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Scenes;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;
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
            RenderPipelineAsset pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null || pipeline.defaultMaterial == null)
            {
                EditorUtility.DisplayDialog("Jelly and Sphere sample",
                    "No render pipeline with a default material is active. Entities Graphics draws with URP (Forward+) or HDRP: "
                    + "assign a pipeline asset in Project Settings > Graphics, then build the sample again.", "OK");
                return;
            }
            if (!EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo())
                return;

            string folder = SampleFolder();
            string mainPath = $"{folder}/{k_MainSceneName}.unity";
            string subPath = $"{folder}/{k_SubSceneName}.unity";
            if ((AssetExists(mainPath) || AssetExists(subPath))
                && !EditorUtility.DisplayDialog("Jelly and Sphere sample",
                    $"Rebuild {mainPath} and {subPath}? Changes you made to them are lost.", "Rebuild", "Cancel"))
                return;

            string materialFolder = EnsureFolder(folder, "Materials");
            Material jelly = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Jelly.mat", new Color(0.35f, 0.85f, 0.4f));
            Material rubber = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Rubber.mat", new Color(0.95f, 0.35f, 0.2f));
            Material steps = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Steps.mat", new Color(0.62f, 0.62f, 0.68f));
            Material floor = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Floor.mat", new Color(0.32f, 0.33f, 0.36f));

            // A new main scene first: the temporary primitives the mesh copies are read from live in it.
            Scene main = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            string meshFolder = EnsureFolder(folder, "Meshes");
            Mesh cube = CreateReadableCopy(PrimitiveType.Cube, $"{meshFolder}/SoftCube.asset");
            Mesh sphere = CreateReadableCopy(PrimitiveType.Sphere, $"{meshFolder}/SoftSphere.asset");
            AssetDatabase.SaveAssets();

            AddCamera(main);
            AddLight(main);

            Scene sub = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Additive);
            AddFloor(sub, floor);
            AddSteps(sub, steps);
            AddSoftBody(sub, "Jelly Cube A", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(0.6f, 4f, -0.7f), Quaternion.identity);
            AddSoftBody(sub, "Jelly Cube B", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(2.1f, 5.5f, 0.6f), Quaternion.Euler(0f, 20f, 10f));
            AddSoftBody(sub, "Jelly Cube C", cube, SoftBodyPreset.Jelly, 1f, jelly, new Vector3(-0.2f, 7f, 0.2f), Quaternion.Euler(15f, 30f, 0f));
            AddSoftBody(sub, "Rubber Sphere", sphere, SoftBodyPreset.Rubber, 0.5f, rubber, new Vector3(3.6f, 6f, -0.5f), Quaternion.identity);
            EditorSceneManager.SaveScene(sub, subPath);
            EditorSceneManager.CloseScene(sub, true);

            // As Entities' own "New Sub Scene" does: add the SubScene inactive, point it at the scene, then enable it.
            var subSceneObject = new GameObject(k_SubSceneName);
            subSceneObject.SetActive(false);
            SceneManager.MoveGameObjectToScene(subSceneObject, main);
            SubScene subScene = subSceneObject.AddComponent<SubScene>();
            subScene.SceneAsset = (SceneAsset)AssetDatabase.LoadAssetAtPath(subPath, typeof(SceneAsset));
            subScene.AutoLoadScene = true;
            subSceneObject.SetActive(true);
            EditorSceneManager.SaveScene(main, mainPath);

            Selection.activeObject = subSceneObject;
            Debug.Log($"Jelly and Sphere sample built: {mainPath} (open) and {subPath}. Press Play to drop the bodies onto the steps.");
        }

        /// <summary>The folder of the imported sample: the parent of the Editor folder holding this script.</summary>
        static string SampleFolder()
        {
            foreach (string guid in AssetDatabase.FindAssets(k_ScriptName))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                if (!path.EndsWith($"/{k_ScriptName}.cs") || !path.StartsWith("Assets/"))
                    continue;
                string editorFolder = Path.GetDirectoryName(path)?.Replace('\\', '/');
                string sampleFolder = Path.GetDirectoryName(editorFolder)?.Replace('\\', '/');
                if (!string.IsNullOrEmpty(sampleFolder))
                    return sampleFolder;
            }
            return EnsureFolder(EnsureFolder("Assets", "Samples"), "JellyAndSphere");
        }

        static string EnsureFolder(string parent, string name)
        {
            string path = $"{parent}/{name}";
            if (!AssetDatabase.IsValidFolder(path))
                AssetDatabase.CreateFolder(parent, name);
            return path;
        }

        static bool AssetExists(string path) => AssetDatabase.LoadAssetAtPath(path, typeof(Object)) != null;

        static Material CreateMaterial(Material template, string path, Color color)
        {
            var material = new Material(template) { color = color };
            AssetDatabase.CreateAsset(material, path);
            return material;
        }

        static void AddCamera(Scene scene)
        {
            var camera = new GameObject("Main Camera");
            camera.tag = "MainCamera";
            camera.AddComponent<Camera>().fieldOfView = 50f;
            camera.transform.position = new Vector3(2.25f, 4.5f, -10f);
            camera.transform.rotation = Quaternion.Euler(14f, 0f, 0f);
            SceneManager.MoveGameObjectToScene(camera, scene);
        }

        static void AddLight(Scene scene)
        {
            var lightObject = new GameObject("Directional Light");
            Light light = lightObject.AddComponent<Light>();
            light.type = LightType.Directional;
            light.intensity = 1.2f;
            light.shadows = LightShadows.Soft;
            lightObject.transform.rotation = Quaternion.Euler(50f, -30f, 0f);
            SceneManager.MoveGameObjectToScene(lightObject, scene);
        }

        static void AddFloor(Scene scene, Material material)
        {
            // Unity's plane primitive is 10 m × 10 m; scaled to 24 m. The collider is an infinite plane through its centre.
            GameObject floor = CreateVisual("Floor", PrimitiveType.Plane, material, scene);
            floor.transform.position = new Vector3(2.25f, 0f, 0f);
            floor.transform.localScale = new Vector3(2.4f, 1f, 2.4f);
            floor.AddComponent<SoftBodyColliderAuthoring>().shape = ColliderShapeType.Plane;
        }

        static void AddSteps(Scene scene, Material material)
        {
            for (int i = 0; i < k_Steps.Length; i++)
            {
                (float x, float height) = k_Steps[i];
                GameObject step = CreateVisual($"Step {i + 1}", PrimitiveType.Cube, material, scene);
                step.transform.position = new Vector3(x, 0.5f * height, 0f);
                step.transform.localScale = new Vector3(k_StepDepth, height, k_StepWidth);
                // The default box (1 m cube at the centre) matches the cube mesh; the Transform's scale sizes both.
                step.AddComponent<SoftBodyColliderAuthoring>().shape = ColliderShapeType.Box;
            }
        }

        static void AddSoftBody(Scene scene, string name, Mesh mesh, SoftBodyPreset preset, float mass, Material material,
            Vector3 position, Quaternion rotation)
        {
            GameObject body = CreateVisual(name, PrimitiveType.Cube, material, scene);
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

        /// <summary>
        /// Saves a readable copy of Unity's built-in <paramref name="primitive"/> mesh at <paramref name="path"/>:
        /// positions and triangles (the Editor can read any mesh), normals recalculated. A mesh created from script
        /// is always readable, so the copy works in players too.
        /// </summary>
        static Mesh CreateReadableCopy(PrimitiveType primitive, string path)
        {
            GameObject temporary = GameObject.CreatePrimitive(primitive);
            Mesh source = temporary.GetComponent<MeshFilter>().sharedMesh;
            var copy = new Mesh
            {
                name = Path.GetFileNameWithoutExtension(path),
                vertices = source.vertices,
                triangles = source.triangles,
            };
            copy.RecalculateNormals();
            copy.RecalculateBounds();
            Object.DestroyImmediate(temporary);
            AssetDatabase.CreateAsset(copy, path);
            return copy;
        }

        /// <summary>A primitive with its MeshFilter and MeshRenderer only (no physics collider), in <paramref name="scene"/>.</summary>
        static GameObject CreateVisual(string name, PrimitiveType primitive, Material material, Scene scene)
        {
            GameObject gameObject = GameObject.CreatePrimitive(primitive);
            gameObject.name = name;
            foreach (Component component in gameObject.GetComponents<Component>())
                if (!(component is Transform) && !(component is MeshFilter) && !(component is MeshRenderer))
                    Object.DestroyImmediate(component);
            gameObject.GetComponent<MeshRenderer>().sharedMaterial = material;
            SceneManager.MoveGameObjectToScene(gameObject, scene);
            return gameObject;
        }
    }
}
