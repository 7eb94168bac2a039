using System.IO;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Scenes;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;

namespace SoftBodyDynamics.Editor
{
    /// <summary>Where a sample's scenes go: its folder (next to its builder script) and the two scene paths.</summary>
    public readonly struct SampleScenePaths
    {
        /// <summary>The imported sample's folder (Assets/…).</summary>
        public readonly string Folder;
        /// <summary>The main scene (camera, light, the SubScene).</summary>
        public readonly string MainScene;
        /// <summary>The SubScene that holds the authoring GameObjects.</summary>
        public readonly string SubScene;
        /// <summary>Name of the SubScene GameObject in the main scene.</summary>
        public readonly string SubSceneName;

        public SampleScenePaths(string folder, string mainSceneName, string subSceneName)
        {
            Folder = folder;
            MainScene = $"{folder}/{mainSceneName}.unity";
            SubScene = $"{folder}/{subSceneName}.unity";
            SubSceneName = subSceneName;
        }
    }

    /// <summary>
    /// What every sample's scene builder does the same way: checks for a render pipeline, asks before overwriting, makes
    /// materials and readable primitive meshes, a camera, a light, a floor collider, and saves a main scene that loads a
    /// SubScene. Each sample keeps only what it places.
    /// </summary>
    public static class SampleSceneBuilder
    {
        /// <summary>
        /// Checks that a render pipeline with a default material is active (Entities Graphics needs URP or HDRP), saves the
        /// user's modified scenes if they want, finds the sample's folder from <paramref name="scriptName"/> (the builder
        /// script's file name, without .cs) and asks before rebuilding existing scenes. False = the user or the project said no.
        /// </summary>
        public static bool TryBegin(string title, string scriptName, string fallbackFolderName, string mainSceneName, string subSceneName,
            out SampleScenePaths paths, out Material template)
        {
            paths = default;
            template = null;
            RenderPipelineAsset pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null || pipeline.defaultMaterial == null)
            {
                EditorUtility.DisplayDialog(title,
                    "No render pipeline with a default material is active. Entities Graphics draws with URP (Forward+) or HDRP: "
                    + "assign a pipeline asset in Project Settings > Graphics, then build the sample again.", "OK");
                return false;
            }
            if (!EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo())
                return false;
            paths = new SampleScenePaths(SampleFolder(scriptName, fallbackFolderName), mainSceneName, subSceneName);
            if ((AssetExists(paths.MainScene) || AssetExists(paths.SubScene))
                && !EditorUtility.DisplayDialog(title,
                    $"Rebuild {paths.MainScene} and {paths.SubScene}? Changes you made to them are lost.", "Rebuild", "Cancel"))
                return false;
            template = pipeline.defaultMaterial;
            return true;
        }

        /// <summary>The folder of the imported sample: the parent of the Editor folder holding <paramref name="scriptName"/>.cs.</summary>
        static string SampleFolder(string scriptName, string fallbackFolderName)
        {
            foreach (string guid in AssetDatabase.FindAssets(scriptName))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                if (!path.EndsWith($"/{scriptName}.cs") || !path.StartsWith("Assets/"))
                    continue;
                string editorFolder = Path.GetDirectoryName(path)?.Replace('\\', '/');
                string sampleFolder = Path.GetDirectoryName(editorFolder)?.Replace('\\', '/');
                if (!string.IsNullOrEmpty(sampleFolder))
                    return sampleFolder;
            }
            return EnsureFolder(EnsureFolder("Assets", "Samples"), fallbackFolderName);
        }

        /// <summary>The folder <paramref name="parent"/>/<paramref name="name"/>, created if missing.</summary>
        public static string EnsureFolder(string parent, string name)
        {
            string path = $"{parent}/{name}";
            if (!AssetDatabase.IsValidFolder(path))
                AssetDatabase.CreateFolder(parent, name);
            return path;
        }

        static bool AssetExists(string path) => AssetDatabase.LoadAssetAtPath(path, typeof(Object)) != null;

        /// <summary>A copy of <paramref name="template"/> in <paramref name="color"/>, saved at <paramref name="path"/>.</summary>
        public static Material CreateMaterial(Material template, string path, Color color)
        {
            var material = new Material(template) { color = color };
            AssetDatabase.CreateAsset(material, path);
            return material;
        }

        /// <summary>
        /// Saves a readable copy of Unity's built-in <paramref name="primitive"/> mesh at <paramref name="path"/>:
        /// positions and triangles (the Editor can read any mesh), normals recalculated. A mesh created from script
        /// is always readable, so the copy works in players too (a soft body deforms its own copy at run time).
        /// </summary>
        public static Mesh CreateReadableCopy(PrimitiveType primitive, string path)
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

        /// <summary>A camera tagged MainCamera (50° field of view) at <paramref name="position"/>, in <paramref name="scene"/>.</summary>
        public static void AddCamera(Scene scene, Vector3 position, Quaternion rotation)
        {
            var camera = new GameObject("Main Camera");
            camera.tag = "MainCamera";
            camera.AddComponent<Camera>().fieldOfView = 50f;
            camera.transform.position = position;
            camera.transform.rotation = rotation;
            SceneManager.MoveGameObjectToScene(camera, scene);
        }

        /// <summary>A directional light with soft shadows, in <paramref name="scene"/>.</summary>
        public static void AddLight(Scene scene)
        {
            var lightObject = new GameObject("Directional Light");
            Light light = lightObject.AddComponent<Light>();
            light.type = LightType.Directional;
            light.intensity = 1.2f;
            light.shadows = LightShadows.Soft;
            lightObject.transform.rotation = Quaternion.Euler(50f, -30f, 0f);
            SceneManager.MoveGameObjectToScene(lightObject, scene);
        }

        /// <summary>A 24 m floor (Unity's 10 m plane primitive scaled) centred at <paramref name="position"/>, with an infinite plane collider through its centre.</summary>
        public static void AddFloor(Scene scene, Material material, Vector3 position)
        {
            GameObject floor = CreateVisual("Floor", PrimitiveType.Plane, material, scene);
            floor.transform.position = position;
            floor.transform.localScale = new Vector3(2.4f, 1f, 2.4f);
            floor.AddComponent<ParticleColliderAuthoring>().shape = ColliderShapeType.Plane;
        }

        /// <summary>A primitive with its MeshFilter and MeshRenderer only (no physics collider), in <paramref name="scene"/>.</summary>
        public static GameObject CreateVisual(string name, PrimitiveType primitive, Material material, Scene scene)
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

        /// <summary>
        /// Saves and closes <paramref name="sub"/>, adds a SubScene that loads it to <paramref name="main"/> (as Entities' own
        /// "New Sub Scene" does: added inactive, pointed at the scene, then enabled), saves the main scene and selects the SubScene.
        /// </summary>
        public static void SaveWithSubScene(Scene main, Scene sub, in SampleScenePaths paths)
        {
            EditorSceneManager.SaveScene(sub, paths.SubScene);
            EditorSceneManager.CloseScene(sub, true);
            var subSceneObject = new GameObject(paths.SubSceneName);
            subSceneObject.SetActive(false);
            SceneManager.MoveGameObjectToScene(subSceneObject, main);
            SubScene subScene = subSceneObject.AddComponent<SubScene>();
            subScene.SceneAsset = (SceneAsset)AssetDatabase.LoadAssetAtPath(paths.SubScene, typeof(SceneAsset));
            subScene.AutoLoadScene = true;
            subSceneObject.SetActive(true);
            EditorSceneManager.SaveScene(main, paths.MainScene);
            Selection.activeObject = subSceneObject;
        }
    }
}
