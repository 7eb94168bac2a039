using System.IO;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Scenes;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;
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
            RenderPipelineAsset pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null || pipeline.defaultMaterial == null)
            {
                EditorUtility.DisplayDialog("Three Methods sample",
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
                && !EditorUtility.DisplayDialog("Three Methods sample",
                    $"Rebuild {mainPath} and {subPath}? Changes you made to them are lost.", "Rebuild", "Cancel"))
                return;

            string materialFolder = EnsureFolder(folder, "Materials");
            Material shapeMatching = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/ShapeMatching.mat", new Color(0.35f, 0.85f, 0.4f));
            Material massSpring = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/MassSpring.mat", new Color(0.95f, 0.6f, 0.2f));
            Material fem = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Fem.mat", new Color(0.3f, 0.55f, 0.95f));
            Material floor = CreateMaterial(pipeline.defaultMaterial, $"{materialFolder}/Floor.mat", new Color(0.32f, 0.33f, 0.36f));

            // A new main scene first: the temporary primitive the mesh copy is read from lives in it.
            Scene main = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            string meshFolder = EnsureFolder(folder, "Meshes");
            Mesh cube = CreateReadableCopy(PrimitiveType.Cube, $"{meshFolder}/SoftCube.asset");
            AssetDatabase.SaveAssets();

            AddCamera(main);
            AddLight(main);

            // The same cube, the same Jelly preset (one physical material), the same drop: only the method differs.
            Scene sub = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Additive);
            AddFloor(sub, floor);
            Quaternion tilt = Quaternion.Euler(20f, 0f, 15f);
            AddSoftBody(sub, "Jelly Cube (Shape Matching)", cube, SoftBodyMethod.ShapeMatching, shapeMatching, new Vector3(-k_Spacing, k_DropHeight, 0f), tilt);
            AddSoftBody(sub, "Jelly Cube (Mass Spring)", cube, SoftBodyMethod.MassSpring, massSpring, new Vector3(0f, k_DropHeight, 0f), tilt);
            AddSoftBody(sub, "Jelly Cube (FEM)", cube, SoftBodyMethod.Fem, fem, new Vector3(k_Spacing, k_DropHeight, 0f), tilt);
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
            Debug.Log($"Three Methods sample built: {mainPath} (open) and {subPath}. Press Play to drop the three cubes.");
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
            return EnsureFolder(EnsureFolder("Assets", "Samples"), "ThreeMethods");
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
            camera.transform.position = new Vector3(0f, 2.5f, -8f);
            camera.transform.rotation = Quaternion.Euler(10f, 0f, 0f);
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
            floor.transform.position = Vector3.zero;
            floor.transform.localScale = new Vector3(2.4f, 1f, 2.4f);
            floor.AddComponent<SoftBodyColliderAuthoring>().shape = ColliderShapeType.Plane;
        }

        static void AddSoftBody(Scene scene, string name, Mesh mesh, SoftBodyMethod method, Material material, Vector3 position,
            Quaternion rotation)
        {
            GameObject body = CreateVisual(name, PrimitiveType.Cube, material, scene);
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
