#version 150
#ifndef GL_ES
#define highp
#define mediump
#define lowp
#endif // GL_ES
#define attribute in
#define varying out


/*=========================================================================

  Program:   Visualization Toolkit
  Module:    vtkPolyDataVS.glsl

  Copyright (c) Ken Martin, Will Schroeder, Bill Lorensen
  All rights reserved.
  See Copyright.txt or http://www.kitware.com/Copyright.htm for details.

     This software is distributed WITHOUT ANY WARRANTY; without even
     the implied warranty of MERCHANTABILITY or FITNESS FOR A PARTICULAR
     PURPOSE.  See the above copyright notice for more information.

=========================================================================*/

in vec4 vertexMC;



// frag position in VC
out vec4 vertexVCVSOutput;

// optional normal declaration
//VTK::Normal::Dec
in vec3 normalMC;
uniform mat3 normalMatrix;
out vec3 normalVCVSOutput;

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
out vec3 shadelabFront;
out vec3 shadelabBack;


// Texture coordinates
//VTK::TCoord::Dec

// material property values
//VTK::Color::Dec

// clipping plane vars
//VTK::Clip::Dec

// camera and actor matrix values
uniform mat4 MCDCMatrix;
uniform mat4 MCVCMatrix;

// Apple Bug
//VTK::PrimID::Dec

// Value raster
//VTK::ValuePass::Dec

// picking support
//VTK::Picking::Dec

void main()
{
  //VTK::CustomBegin::Impl

  //VTK::Color::Impl

  normalVCVSOutput = normalMatrix * normalMC;
//VTK::Normal::Impl

  //VTK::TCoord::Impl

  //VTK::Clip::Impl

  //VTK::PrimID::Impl

  vertexVCVSOutput = MCVCMatrix * vertexMC;
  gl_Position = MCDCMatrix * vertexMC;


  //VTK::ValuePass::Impl

    {
    vec3 n = normalVCVSOutput;
    float len = length(n);
    if (len > shadelabTinyLength && !isinf(len))
    {
      shadelabFront = shadelabIlluminate(vertexVCVSOutput.xyz, n / len);
      shadelabBack = shadelabIlluminate(vertexVCVSOutput.xyz, -n / len);
    }
    else
    {
      shadelabFront = shadelabKa * shadelabIa; // shadelab: ambient
      shadelabBack = shadelabFront;
    }
  }


  //VTK::Picking::Impl

  //VTK::CustomEnd::Impl
}
