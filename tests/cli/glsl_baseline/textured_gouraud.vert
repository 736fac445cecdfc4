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
in vec2 shadelabTCoord;
out vec2 shadelabTCoordVSOutput;
// shadelab: the lecture's illumination model (shadelabShadingOracle.cxx)
uniform vec3 shadelabKa;
uniform vec3 shadelabKd;
uniform vec3 shadelabKs;
uniform float shadelabNs;
uniform vec3 shadelabIa;
uniform int shadelabOrthographic;
uniform vec3 shadelabLightColor[1];
uniform vec3 shadelabLightPosition[1];
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
  vec3 sum = L + V;
  float len = length(sum);
  if (!(len > shadelabTinyLength))
  {
    return -1.0;
  }
  vec3 H = sum / len;
  return dot(N, H) > 0.0 ? 0.5 * dot(N - H, N - H) : -1.0;
}

// The equation's parts, for the fragment to multiply by its texel:
// D = sum_l Il*kd*max(N.L, 0), S = sum_l Il*S_l (ka*Ia is the fragment's).
void shadelabIlluminateApart(vec3 P, vec3 N, out vec3 D, out vec3 S)
{
  D = vec3(0.0);
  S = vec3(0.0);
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
    D += Il * (NdotL * shadelabKd); // shadelab: diffuse
    d = shadelabSpecularD(N, L, V); // shadelab: specular
    if (d >= 0.0)
    {
      S += Il * (shadelabSpecularFalloff(d, shadelabNs) * shadelabKs); // shadelab: specular
    }
  }
}
out vec3 shadelabFrontDiffuse;
out vec3 shadelabFrontSpecular;
out vec3 shadelabBackDiffuse;
out vec3 shadelabBackSpecular;


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

    shadelabTCoordVSOutput = shadelabTCoord;
  {
    vec3 n = normalVCVSOutput;
    float len = length(n);
    shadelabFrontDiffuse = vec3(0.0);
    shadelabFrontSpecular = vec3(0.0);
    shadelabBackDiffuse = vec3(0.0);
    shadelabBackSpecular = vec3(0.0);
    if (len > shadelabTinyLength && !isinf(len))
    {
      shadelabIlluminateApart(
        vertexVCVSOutput.xyz, n / len, shadelabFrontDiffuse, shadelabFrontSpecular);
      shadelabIlluminateApart(
        vertexVCVSOutput.xyz, -n / len, shadelabBackDiffuse, shadelabBackSpecular);
    }
  }


  //VTK::Picking::Impl

  //VTK::CustomEnd::Impl
}
