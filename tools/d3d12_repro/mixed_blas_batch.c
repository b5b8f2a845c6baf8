/* mixed_blas_batch.c: minimal D3D12 + DXR reproduction of the one systematic
 * difference found between Penumbra's D3D12 and Vulkan images on lavapipe
 * (docs/windows.md, "Known problems"). Recorded in one command list: a
 * triangle BLAS build; a copy of one AABB into a default-heap buffer and its
 * transition to NON_PIXEL_SHADER_RESOURCE; an AABB BLAS build from it; a
 * TLAS over both; DispatchRays. That is valid D3D12 (each build has its own
 * result and scratch, the AABB buffer is in the state a build input needs),
 * yet under vkd3d-proton 3.0.1 on lavapipe (Mesa 25.0.7) no ray hits the
 * box. With `--barrier` (a UAV barrier on the triangle BLAS right after its
 * build) every ray through the box hits it. A UAV barrier after the copy or
 * after the transition does not help.
 *   bash tools/d3d12_repro/run.sh
 * Exit status 0 when the box is hit. Built from the toolchain check in
 * ../shared/tools/d3d12-on-linux/dxr_smoke (dxr_smoke.c). */
#define COBJMACROS
#define INITGUID
#ifndef _WIN32
#define WIDL_C_INLINE_WRAPPERS
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _WIN32
#include <windows.h>
#include <initguid.h>
#ifdef USE_DIRECTX_HEADERS
#include <directx/d3d12.h>   /* Microsoft DirectX-Headers, as Penumbra's cross build uses */
#else
#include <d3d12.h>           /* mingw-w64's own */
#endif
#define U(s) L##s
#else
#include <unistd.h>
#include "vkd3d_windows.h"
#include "vkd3d_d3d12.h"
#define U(s) u##s
#endif

#define W 16
#define H 8
#define CHECK(x) do { HRESULT hr_ = (x); if (FAILED(hr_)) { fprintf(stderr, "FAILED %s:%d: %s -> 0x%08x\n", __FILE__, __LINE__, #x, (unsigned)hr_); exit(2); } } while (0)

static ID3D12Device5 *dev;

static ID3D12Resource *buffer(D3D12_HEAP_TYPE heap, UINT64 size, D3D12_RESOURCE_FLAGS flags, D3D12_RESOURCE_STATES state)
{
    D3D12_HEAP_PROPERTIES hp;
    D3D12_RESOURCE_DESC rd;
    ID3D12Resource *r;
    memset(&hp, 0, sizeof(hp)); hp.Type = heap;
    memset(&rd, 0, sizeof(rd));
    rd.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER; rd.Width = size; rd.Height = 1; rd.DepthOrArraySize = 1;
    rd.MipLevels = 1; rd.SampleDesc.Count = 1; rd.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR; rd.Flags = flags;
    rd.Format = DXGI_FORMAT_UNKNOWN;
    CHECK(ID3D12Device5_CreateCommittedResource(dev, &hp, D3D12_HEAP_FLAG_NONE, &rd, state, NULL, &IID_ID3D12Resource, (void **)&r));
    return r;
}

static ID3D12Resource *upload(const void *data, UINT64 size)
{
    ID3D12Resource *r = buffer(D3D12_HEAP_TYPE_UPLOAD, size, D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_GENERIC_READ);
    void *p;
    CHECK(ID3D12Resource_Map(r, 0, NULL, &p));
    memcpy(p, data, size);
    ID3D12Resource_Unmap(r, 0, NULL);
    return r;
}

static void uav_barrier(ID3D12GraphicsCommandList4 *cl, ID3D12Resource *r)
{
    D3D12_RESOURCE_BARRIER b;
    memset(&b, 0, sizeof(b));
    b.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
    b.UAV.pResource = r;
    ID3D12GraphicsCommandList4_ResourceBarrier(cl, 1, &b);
}

static ID3D12Resource *build_as(ID3D12GraphicsCommandList4 *cl, const D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS *in, ID3D12Resource **scratch, int barrier)
{
    D3D12_RAYTRACING_ACCELERATION_STRUCTURE_PREBUILD_INFO info;
    D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_DESC bd;
    ID3D12Resource *as;
    ID3D12Device5_GetRaytracingAccelerationStructurePrebuildInfo(dev, in, &info);
    as = buffer(D3D12_HEAP_TYPE_DEFAULT, info.ResultDataMaxSizeInBytes, D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS,
                D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE);
    *scratch = buffer(D3D12_HEAP_TYPE_DEFAULT, info.ScratchDataSizeInBytes ? info.ScratchDataSizeInBytes : 256,
                      D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS, D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
    memset(&bd, 0, sizeof(bd));
    bd.DestAccelerationStructureData = ID3D12Resource_GetGPUVirtualAddress(as);
    bd.Inputs = *in;
    bd.ScratchAccelerationStructureData = ID3D12Resource_GetGPUVirtualAddress(*scratch);
    ID3D12GraphicsCommandList4_BuildRaytracingAccelerationStructure(cl, &bd, 0, NULL);
    if (barrier) uav_barrier(cl, as);
    return as;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "mixed_blas_batch.dxil";
    const int barrier = argc > 2 && !strcmp(argv[2], "--barrier");
    D3D12_COMMAND_QUEUE_DESC qd;
    ID3D12CommandQueue *queue;
    ID3D12CommandAllocator *alloc;
    ID3D12GraphicsCommandList4 *cl;
    ID3D12Fence *fence;
    ID3D12Resource *vb, *ab, *blas_tri, *blas_box, *tlas, *s0, *s1, *s2, *inst_buf, *out, *rb, *st;
    ID3D12RootSignature *rs;
    ID3D10Blob *blob, *err = NULL;
    ID3D12StateObject *so;
    ID3D12StateObjectProperties *props;
    D3D12_RAYTRACING_GEOMETRY_DESC geom;
    D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS in;
    D3D12_RAYTRACING_INSTANCE_DESC inst[2];
    D3D12_ROOT_PARAMETER params[2];
    D3D12_ROOT_SIGNATURE_DESC rsd;
    D3D12_DXIL_LIBRARY_DESC lib;
    D3D12_HIT_GROUP_DESC hg[2];
    D3D12_RAYTRACING_SHADER_CONFIG sc;
    D3D12_GLOBAL_ROOT_SIGNATURE grs;
    D3D12_RAYTRACING_PIPELINE_CONFIG pc;
    D3D12_STATE_SUBOBJECT subs[6];
    D3D12_STATE_OBJECT_DESC sod;
    D3D12_DISPATCH_RAYS_DESC dr;
    D3D12_RESOURCE_BARRIER b;
    unsigned char table[256];
    const void *ids[4];
    float (*px)[4];
    void *code; long code_size; FILE *f;
    int x, y, box_hits = 0;
    /* A triangle low in the picture (instance 0) and a box high in it (instance 1). */
    static const float verts[] = { -0.9f, -0.9f, 0.0f,  0.9f, -0.9f, 0.0f,  0.0f, -0.3f, 0.0f };
    static const float box[] = { -0.5f, 0.1f, -0.5f,  0.5f, 0.9f, 0.5f };

    if (!(f = fopen(path, "rb"))) { perror(path); return 2; }
    fseek(f, 0, SEEK_END); code_size = ftell(f); fseek(f, 0, SEEK_SET);
    code = malloc(code_size);
    if (fread(code, 1, code_size, f) != (size_t)code_size) { perror("read"); return 2; }
    fclose(f);

    CHECK(D3D12CreateDevice(NULL, D3D_FEATURE_LEVEL_11_0, &IID_ID3D12Device5, (void **)&dev));
    memset(&qd, 0, sizeof(qd)); qd.Type = D3D12_COMMAND_LIST_TYPE_DIRECT;
    CHECK(ID3D12Device5_CreateCommandQueue(dev, &qd, &IID_ID3D12CommandQueue, (void **)&queue));
    CHECK(ID3D12Device5_CreateCommandAllocator(dev, D3D12_COMMAND_LIST_TYPE_DIRECT, &IID_ID3D12CommandAllocator, (void **)&alloc));
    CHECK(ID3D12Device5_CreateCommandList(dev, 0, D3D12_COMMAND_LIST_TYPE_DIRECT, alloc, NULL, &IID_ID3D12GraphicsCommandList4, (void **)&cl));
    CHECK(ID3D12Device5_CreateFence(dev, 0, D3D12_FENCE_FLAG_NONE, &IID_ID3D12Fence, (void **)&fence));

    /* Two bottom levels: a triangle BLAS, then an AABB BLAS. */
    vb = upload(verts, sizeof(verts));
    ab = upload(box, sizeof(box));
    memset(&in, 0, sizeof(in));
    in.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL;
    in.Flags = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_TRACE;
    in.NumDescs = 1;
    in.DescsLayout = D3D12_ELEMENTS_LAYOUT_ARRAY;
    in.pGeometryDescs = &geom;
    memset(&geom, 0, sizeof(geom));
    geom.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_TRIANGLES;
    geom.Flags = D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE;
    geom.Triangles.VertexBuffer.StartAddress = ID3D12Resource_GetGPUVirtualAddress(vb);
    geom.Triangles.VertexBuffer.StrideInBytes = 12;
    geom.Triangles.VertexFormat = DXGI_FORMAT_R32G32B32_FLOAT;
    geom.Triangles.VertexCount = 3;
    geom.Triangles.IndexFormat = DXGI_FORMAT_UNKNOWN;
    blas_tri = build_as(cl, &in, &s0, barrier);
    /* The box's AABB reaches a default-heap buffer by a copy recorded after
     * the triangle build, and is made a build input by a transition. */
    {
        ID3D12Resource *staging = ab;
        ab = buffer(D3D12_HEAP_TYPE_DEFAULT, sizeof(box), D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_COPY_DEST);
        ID3D12GraphicsCommandList4_CopyBufferRegion(cl, ab, 0, staging, 0, sizeof(box));
        memset(&b, 0, sizeof(b));
        b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
        b.Transition.pResource = ab;
        b.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
        b.Transition.StateBefore = D3D12_RESOURCE_STATE_COPY_DEST;
        b.Transition.StateAfter = D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE;
        ID3D12GraphicsCommandList4_ResourceBarrier(cl, 1, &b);
    }
    memset(&geom, 0, sizeof(geom));
    geom.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_PROCEDURAL_PRIMITIVE_AABBS;
    geom.Flags = D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE;
    geom.AABBs.AABBCount = 1;
    geom.AABBs.AABBs.StartAddress = ID3D12Resource_GetGPUVirtualAddress(ab);
    geom.AABBs.AABBs.StrideInBytes = 24;
    blas_box = build_as(cl, &in, &s1, 1);

    memset(inst, 0, sizeof(inst));
    for (x = 0; x < 2; x++)
    {
        inst[x].Transform[0][0] = inst[x].Transform[1][1] = inst[x].Transform[2][2] = 1.0f;
        inst[x].InstanceMask = 0xff;
        inst[x].InstanceContributionToHitGroupIndex = x;
        inst[x].AccelerationStructure = ID3D12Resource_GetGPUVirtualAddress(x ? blas_box : blas_tri);
    }
    inst_buf = upload(inst, sizeof(inst));
    memset(&in, 0, sizeof(in));
    in.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL;
    in.Flags = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_TRACE;
    in.NumDescs = 2;
    in.DescsLayout = D3D12_ELEMENTS_LAYOUT_ARRAY;
    in.InstanceDescs = ID3D12Resource_GetGPUVirtualAddress(inst_buf);
    tlas = build_as(cl, &in, &s2, 1);

    out = buffer(D3D12_HEAP_TYPE_DEFAULT, W * H * 16, D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS, D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
    rb = buffer(D3D12_HEAP_TYPE_READBACK, W * H * 16, D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_COPY_DEST);

    memset(params, 0, sizeof(params));
    params[0].ParameterType = D3D12_ROOT_PARAMETER_TYPE_SRV;
    params[0].ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
    params[1].ParameterType = D3D12_ROOT_PARAMETER_TYPE_UAV;
    params[1].ShaderVisibility = D3D12_SHADER_VISIBILITY_ALL;
    memset(&rsd, 0, sizeof(rsd));
    rsd.NumParameters = 2; rsd.pParameters = params;
    CHECK(D3D12SerializeRootSignature(&rsd, D3D_ROOT_SIGNATURE_VERSION_1, &blob, &err));
    CHECK(ID3D12Device5_CreateRootSignature(dev, 0, ID3D10Blob_GetBufferPointer(blob), ID3D10Blob_GetBufferSize(blob),
                                            &IID_ID3D12RootSignature, (void **)&rs));

    memset(&lib, 0, sizeof(lib));
    lib.DXILLibrary.pShaderBytecode = code; lib.DXILLibrary.BytecodeLength = code_size;
    memset(hg, 0, sizeof(hg));
    hg[0].HitGroupExport = U("TriangleGroup"); hg[0].Type = D3D12_HIT_GROUP_TYPE_TRIANGLES;
    hg[0].ClosestHitShaderImport = U("TriangleHit");
    hg[1].HitGroupExport = U("BoxGroup"); hg[1].Type = D3D12_HIT_GROUP_TYPE_PROCEDURAL_PRIMITIVE;
    hg[1].ClosestHitShaderImport = U("BoxHit"); hg[1].IntersectionShaderImport = U("BoxIntersection");
    sc.MaxPayloadSizeInBytes = 16; sc.MaxAttributeSizeInBytes = 8;
    grs.pGlobalRootSignature = rs;
    pc.MaxTraceRecursionDepth = 1;
    subs[0].Type = D3D12_STATE_SUBOBJECT_TYPE_DXIL_LIBRARY; subs[0].pDesc = &lib;
    subs[1].Type = D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP; subs[1].pDesc = &hg[0];
    subs[2].Type = D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP; subs[2].pDesc = &hg[1];
    subs[3].Type = D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_SHADER_CONFIG; subs[3].pDesc = &sc;
    subs[4].Type = D3D12_STATE_SUBOBJECT_TYPE_GLOBAL_ROOT_SIGNATURE; subs[4].pDesc = &grs;
    subs[5].Type = D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_PIPELINE_CONFIG; subs[5].pDesc = &pc;
    sod.Type = D3D12_STATE_OBJECT_TYPE_RAYTRACING_PIPELINE; sod.NumSubobjects = 6; sod.pSubobjects = subs;
    CHECK(ID3D12Device5_CreateStateObject(dev, &sod, &IID_ID3D12StateObject, (void **)&so));
    CHECK(ID3D12StateObject_QueryInterface(so, &IID_ID3D12StateObjectProperties, (void **)&props));
    ids[0] = ID3D12StateObjectProperties_GetShaderIdentifier(props, U("RayGen"));
    ids[1] = ID3D12StateObjectProperties_GetShaderIdentifier(props, U("Miss"));
    ids[2] = ID3D12StateObjectProperties_GetShaderIdentifier(props, U("TriangleGroup"));
    ids[3] = ID3D12StateObjectProperties_GetShaderIdentifier(props, U("BoxGroup"));
    for (x = 0; x < 4; x++) if (!ids[x]) { fprintf(stderr, "missing shader identifier %d\n", x); return 4; }
    memset(table, 0, sizeof(table));
    for (x = 0; x < 4; x++) memcpy(table + 64 * x, ids[x], D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES);
    st = upload(table, sizeof(table));

    ID3D12GraphicsCommandList4_SetComputeRootSignature(cl, rs);
    ID3D12GraphicsCommandList4_SetPipelineState1(cl, so);
    ID3D12GraphicsCommandList4_SetComputeRootShaderResourceView(cl, 0, ID3D12Resource_GetGPUVirtualAddress(tlas));
    ID3D12GraphicsCommandList4_SetComputeRootUnorderedAccessView(cl, 1, ID3D12Resource_GetGPUVirtualAddress(out));
    memset(&dr, 0, sizeof(dr));
    dr.RayGenerationShaderRecord.StartAddress = ID3D12Resource_GetGPUVirtualAddress(st);
    dr.RayGenerationShaderRecord.SizeInBytes = 32;
    dr.MissShaderTable.StartAddress = ID3D12Resource_GetGPUVirtualAddress(st) + 64;
    dr.MissShaderTable.SizeInBytes = 64; dr.MissShaderTable.StrideInBytes = 64;
    dr.HitGroupTable.StartAddress = ID3D12Resource_GetGPUVirtualAddress(st) + 128;
    dr.HitGroupTable.SizeInBytes = 128; dr.HitGroupTable.StrideInBytes = 64;
    dr.Width = W; dr.Height = H; dr.Depth = 1;
    ID3D12GraphicsCommandList4_DispatchRays(cl, &dr);

    memset(&b, 0, sizeof(b));
    b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    b.Transition.pResource = out;
    b.Transition.Subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
    b.Transition.StateBefore = D3D12_RESOURCE_STATE_UNORDERED_ACCESS;
    b.Transition.StateAfter = D3D12_RESOURCE_STATE_COPY_SOURCE;
    ID3D12GraphicsCommandList4_ResourceBarrier(cl, 1, &b);
    ID3D12GraphicsCommandList4_CopyResource(cl, rb, out);
    CHECK(ID3D12GraphicsCommandList4_Close(cl));
    ID3D12CommandQueue_ExecuteCommandLists(queue, 1, (ID3D12CommandList **)&cl);
    CHECK(ID3D12CommandQueue_Signal(queue, fence, 1));
    while (ID3D12Fence_GetCompletedValue(fence) < 1)
    {
#ifdef _WIN32
        Sleep(1);
#else
        usleep(1000);
#endif
    }

    CHECK(ID3D12Resource_Map(rb, 0, NULL, (void **)&px));
    for (y = 0; y < H; y++)
    {
        for (x = 0; x < W; x++)
        {
            const float *p = px[y * W + x];
            box_hits += p[0] == 2.0f;
            putchar(p[0] == 1.0f ? 't' : p[0] == 2.0f ? 'B' : p[0] == 0.0f ? '.' : '?');
        }
        putchar('\n');
    }
    ID3D12Resource_Unmap(rb, 0, NULL);
    printf("t = triangle (instance 0), B = box (instance 1, procedural), . = miss\n");
    printf("%s: %d rays hit the box: %s\n", barrier ? "barrier after the triangle build" : "no barrier",
           box_hits, box_hits > 0 ? "PASS" : "FAIL");
    (void)s0; (void)s1; (void)s2;
    return box_hits > 0 ? 0 : 1;
}
