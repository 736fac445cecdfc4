#version 150
#ifdef GL_ES
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
precision highp sampler2D;
precision highp sampler3D;
#else
precision mediump float;
precision mediump sampler2D;
precision mediump sampler3D;
#endif
#define texelFetchBuffer texelFetch
#define texture1D texture
#define texture2D texture
#define texture3D texture
#else // GL_ES
#define highp
#define mediump
#define lowp
#if __VERSION__ == 150
#define texelFetchBuffer texelFetch
#define texture1D texture
#define texture2D texture
#define texture3D texture
#endif
#endif // GL_ES
#define varying in


/*=========================================================================

  Program:   Visualization Toolkit
  Module:    vtkPolyDataFS.glsl

  Copyright (c) Ken Martin, Will Schroeder, Bill Lorensen
  All rights reserved.
  See Copyright.txt or http://www.kitware.com/Copyright.htm for details.

     This software is distributed WITHOUT ANY WARRANTY; without even
     the implied warranty of MERCHANTABILITY or FITNESS FOR A PARTICULAR
     PURPOSE.  See the above copyright notice for more information.

=========================================================================*/
// Template for the polydata mappers fragment shader

uniform int PrimitiveIDOffset;



// VC position of this fragment
in vec4 vertexVCVSOutput;

// Camera prop
uniform int cameraParallel;


// optional color passed in from the vertex shader, vertexColor
uniform float ambientIntensity; // the material ambient
uniform float diffuseIntensity; // the material diffuse
uniform float opacityUniform; // the fragment opacity
uniform vec3 ambientColorUniform; // ambient color
uniform vec3 diffuseColorUniform; // diffuse color
uniform float specularIntensity; // the material specular intensity
uniform vec3 specularColorUniform; // intensity weighted color
uniform float specularPowerUniform;


// optional surface normal declaration
//VTK::Normal::Dec
uniform mat3 normalMatrix;
in vec3 normalVCVSOutput;

// extra lighting parameters
// shadelab: the lecture's illumination model (shadelabShadingOracle.cxx)
uniform vec3 shadelabKa;
uniform vec3 shadelabKd;
uniform vec3 shadelabKs;
uniform float shadelabNs;
uniform vec3 shadelabIa;
uniform int shadelabOrthographic;
uniform vec3 shadelabLightColor[3];
uniform vec3 shadelabLightPosition[3];
uniform vec3 shadelabLightDirection[3];
uniform float shadelabLightCosCutoff[3];
uniform float shadelabLightExponent[3];
const float shadelabTinyLength = 1e-20;
const float shadelabGrazingLimit = 1e-5; // GrazingLimit in the oracle
float shadelabSpecularFalloff(float d, float ns)
{
  if (d < 0.01)
  {
    return exp(-ns * d * (1.0 + d * (0.5 + d * (1.0 / 3.0 + d * 0.25))));
  }
  return pow(1.0 - d, ns);
}

// d = 1 - cos of the specular angle, or -1 when there is no specular term.
float shadelabSpecularD(vec3 N, vec3 L, vec3 V)
{
  vec3 R = (2.0 * dot(N, L)) * N - L;
  return dot(V, R) > 0.0 ? 0.5 * dot(V - R, V - R) : -1.0;
}

// I = ka*Ia + sum_l Il*[kd*max(N.L, 0) + S_l], N unit.
vec3 shadelabIlluminate(vec3 P, vec3 N)
{
  vec3 I = shadelabKa * shadelabIa; // shadelab: ambient
  vec3 V = vec3(0.0, 0.0, 1.0);
  if (shadelabOrthographic == 0)
  {
    float len = length(P);
    V = len > shadelabTinyLength ? -P / len : vec3(0.0);
  }
  vec3 L;
  vec3 Il;
  float NdotL;
  float d;
  vec3 toLight;
  float distance;
  // light 0: point
  Il = shadelabLightColor[0];
  toLight = shadelabLightPosition[0] - P;
  distance = length(toLight);
  L = toLight / max(distance, shadelabTinyLength);
  NdotL = dot(N, L);
  if (distance > shadelabTinyLength && NdotL > shadelabGrazingLimit)
  {
    vec3 term = NdotL * shadelabKd; // shadelab: diffuse
    d = shadelabSpecularD(N, L, V); // shadelab: specular
    if (d >= 0.0)
    {
      term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs; // shadelab: specular
    }
    I += Il * term; // shadelab: diffuse, specular
  }
  // light 1: directional
  Il = shadelabLightColor[1];
  L = -shadelabLightDirection[1];
  NdotL = dot(N, L);
  if (NdotL > shadelabGrazingLimit)
  {
    vec3 term = NdotL * shadelabKd; // shadelab: diffuse
    d = shadelabSpecularD(N, L, V); // shadelab: specular
    if (d >= 0.0)
    {
      term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs; // shadelab: specular
    }
    I += Il * term; // shadelab: diffuse, specular
  }
  // light 2: spot
  Il = shadelabLightColor[2];
  toLight = shadelabLightPosition[2] - P;
  distance = length(toLight);
  L = toLight / max(distance, shadelabTinyLength);
  float cosAngle2 = dot(-L, shadelabLightDirection[2]);
  float exponent2 = shadelabLightExponent[2];
  Il *= exponent2 == 0.0 ? 1.0 : (cosAngle2 > 0.0 ? pow(cosAngle2, exponent2) : 0.0);
  NdotL = dot(N, L);
  if (distance > shadelabTinyLength && cosAngle2 >= shadelabLightCosCutoff[2] && NdotL > shadelabGrazingLimit)
  {
    vec3 term = NdotL * shadelabKd; // shadelab: diffuse
    d = shadelabSpecularD(N, L, V); // shadelab: specular
    if (d >= 0.0)
    {
      term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs; // shadelab: specular
    }
    I += Il * term; // shadelab: diffuse, specular
  }
  return I;
}
uniform vec3 lightColor0;
  uniform vec3 lightDirectionVC0; // normalized


// Texture maps
//VTK::TMap::Dec

// Texture coordinates
//VTK::TCoord::Dec

// picking support
//VTK::Picking::Dec

// Depth Peeling Support
//VTK::DepthPeeling::Dec

// clipping plane vars
//VTK::Clip::Dec

// the output of this shader
// The 8-bit capture: k = round(255*clamp(I)), decided exactly, stored as k/255.
uniform float shadelabHalfSteps[255]; // the least float at or above (k - 0.5)/255, k = 1..255
float shadelabQuantised(float v)
{
  float c = clamp(v, 0.0, 1.0);
  int k = int(c * 255.0 + 0.5); // k or k + 1 (IEEE rounding is monotonic, half steps are floats)
  if (k > 0 && c < shadelabHalfSteps[k - 1])
  {
    k -= 1;
  }
  return float(k) / 255.0;
}
vec4 shadelabQuantised(vec4 v)
{
  return vec4(shadelabQuantised(v.r), shadelabQuantised(v.g), shadelabQuantised(v.b),
    shadelabQuantised(v.a));
}
out vec4 fragOutput0;


// Apple Bug
//VTK::PrimID::Dec

// handle coincident offsets
//VTK::Coincident::Dec

// Value raster
//VTK::ValuePass::Dec

// surface with edges
//VTK::Edges::Dec

void main()
{
  // VC position of this fragment. This should not branch/return/discard.
  vec4 vertexVC = vertexVCVSOutput;

  // Place any calls that require uniform flow (e.g. dFdx) here.
    vec3 shadelabGeometricN = cross(dFdx(vertexVC.xyz), dFdy(vertexVC.xyz));


  // Set gl_FragDepth here (gl_FragCoord.z by default)
  //VTK::Depth::Impl

  // Early depth peeling abort:
  //VTK::DepthPeeling::PreColor

  // Apple Bug
  //VTK::PrimID::Impl

  //VTK::Clip::Impl

  //VTK::ValuePass::Impl

    vec3 specularColor = specularIntensity * specularColorUniform;
  float specularPower = specularPowerUniform;
  vec3 ambientColor = ambientIntensity * ambientColorUniform;
  vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;
  float opacity = opacityUniform;


  //VTK::Edges::Impl

  // Generate the normal if we are not passed in one
  

    vec3 shadelabN;
  float shadelabLength = length(normalVCVSOutput);
  if (shadelabLength > 1e-6 && !isinf(shadelabLength))
  {
    shadelabN = normalVCVSOutput / shadelabLength;
    if (!gl_FrontFacing)
    {
      shadelabN = -shadelabN;
    }
  }
  else
  {
    shadelabN = normalize(shadelabGeometricN);
    vec3 towardsViewer = shadelabOrthographic == 1 ? vec3(0.0, 0.0, 1.0) : -vertexVC.xyz;
    if (dot(shadelabN, towardsViewer) < 0.0)
    {
      shadelabN = -shadelabN;
    }
  }
  fragOutput0 = vec4(shadelabIlluminate(vertexVC.xyz, shadelabN), 1.0);


  //VTK::TCoord::Impl

  if (fragOutput0.a <= 0.0)
    {
    discard;
    }

  //VTK::DepthPeeling::Impl

  //VTK::Picking::Impl

  // handle coincident offsets
  //VTK::Coincident::Impl
  fragOutput0 = shadelabQuantised(fragOutput0);

}
